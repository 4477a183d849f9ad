#!/usr/bin/python3
"""Load-balance model of a full sampling plan (issue 15), from the measured per-sample costs of a thinned one.

usage: tools/loadbalance.py samples.h5 [--cpu-total S] [--n1 150 --n2 50] [--ranks 2,16,128,1024]

samples.h5 is the output of hylc-sample on a thinned plan (-sampler_n1 a -sampler_n2 b, read from
/provenance/options) with the default ranges. Each thinned sample stands for the full-plan samples nearest
it: a 1D sample for n1/a samples of its term, a 2D sample for (n2/b)^2 samples of its grid (n2/b lines of
n2/b samples each). Its measured solve time (/samples/time; rescaled so that the sum is --cpu-total when
given, e.g. the run's user CPU time on a loaded machine) is taken as the cost of each of them.

Units of work, as hylc-sample hands them out (a shared counter: the next unit goes to the first free rank):
  cold      a batch of -sampler_batch samples (1) in plan order;
  continue  a half-line: each 1D term and each line of a 2D grid (along the pair's second coordinate) split
            at zero; a full-plan half-line is the thinned half-line's samples, each repeated.
The makespan of that greedy list schedule is printed for each rank count with its parallel efficiency
(total / (ranks x makespan)) and the largest unit (a lower bound on the makespan); for continuation also
with the units handed out longest first (what an ordering by expected cost would give).
"""
import argparse
import heapq
import h5py
import numpy as np

TERMS = [(), (0,), (1,), (2,), (3,), (5,), (0, 1), (0, 2), (0, 3), (0, 5), (1, 2), (1, 3), (1, 5), (2, 3), (2, 5)]


def option(opts, name, default):
    for o in opts:
        o = o.decode() if isinstance(o, bytes) else o
        k, _, v = o.partition(' ')
        if k == name:
            return int(v)
    return default


def makespan(costs, ranks):
    free = [0.0] * ranks
    heapq.heapify(free)
    for c in costs:
        heapq.heappush(free, heapq.heappop(free) + c)
    return max(free)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('samples')
    ap.add_argument('--cpu-total', type=float, default=None)
    ap.add_argument('--n1', type=int, default=150)
    ap.add_argument('--n2', type=int, default=50)
    ap.add_argument('--batch', type=int, default=1)
    ap.add_argument('--ranks', default='2,16,128,1024')
    a = ap.parse_args()
    f = h5py.File(a.samples, 'r')
    s = f['samples']
    z, term, t = s['strain'][:], s['term'][:], s['time'][:].astype(float)
    opts = f['provenance/options'][:] if 'provenance/options' in f else []
    n1, n2 = option(opts, '-sampler_n1', 150), option(opts, '-sampler_n2', 50)
    if a.cpu_total:
        t *= a.cpu_total / t.sum()
    # a thinned sample stands for w1 = n1/a 1D samples, or w2 x w2 (w2 = n2/b) 2D ones; when w is not an
    # integer, round(w) copies are made, each with cost t w / round(w) (the total is kept)
    w1, w2 = a.n1 / n1, a.n2 / n2
    q1, q2 = max(1, round(w1)), max(1, round(w2))
    # cold: every thinned sample repeated, in plan order
    cold = []
    for k in range(len(t)):
        if term[k] == 0:
            cold.append(t[k])
        elif len(TERMS[term[k]]) == 1:
            cold += [t[k] * w1 / q1] * q1
        else:
            cold += [t[k] * w2 * w2 / (q2 * q2)] * (q2 * q2)
    cold = [sum(cold[i:i + a.batch]) for i in range(0, len(cold), a.batch)]
    # continue: half-lines
    lines = {}
    for k in range(len(t)):
        c = TERMS[term[k]]
        if not c:
            key = ('zero',)
        elif len(c) == 1:
            key = (term[k], z[k, c[0]] >= 0)
        else:
            key = (term[k], round(float(z[k, c[0]]), 12), z[k, c[1]] >= 0)
        lines.setdefault(key, []).append(k)
    cont = []
    for key, ks in lines.items():
        c = sum(t[ks])
        if key[0] == 'zero':
            cont.append(c)
        elif len(key) == 2:
            cont.append(c * w1)
        else:
            cont += [c * w2 * w2 / q2] * q2
    # dict order is plan order: the counter hands the units out in that order
    total = sum(cold)
    print(f'{a.samples}: thinned plan n1 {n1}, n2 {n2} ({len(t)} samples, {t.sum():.1f} s, {t.sum() / len(t):.3f} s per sample) -> full plan n1 {a.n1}, n2 {a.n2}')
    print(f'  projected total: {total:.0f} CPU-s ({total / 3600:.2f} h), {len(cold)} cold units (batch {a.batch}), {len(cont)} half-lines')
    print(f'  largest unit: cold {max(cold):.1f} s, continue {max(cont):.1f} s')
    print('  ranks | cold: wall (h), efficiency | continue (same costs): wall (h), efficiency | continue, longest unit first')
    lpt = sorted(cont, reverse=True)
    for p in [int(x) for x in a.ranks.split(',')]:
        mc, mk, ml = makespan(cold, p), makespan(cont, p), makespan(lpt, p)
        print(f'  {p:5d} | {mc / 3600:9.3f} {total / (p * mc):6.1%} | {mk / 3600:9.3f} {total / (p * mk):6.1%} | {ml / 3600:9.3f} {total / (p * ml):6.1%}')


if __name__ == '__main__':
    main()
