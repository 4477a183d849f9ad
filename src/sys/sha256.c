/* SHA-256 as specified in FIPS 180-4 (include/hylc/sha256.h). */
#include <hylc/sha256.h>
#include <string.h>

static const uint32_t K[64] = {0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5, 0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da, 0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
                               0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85, 0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070, 0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3, 0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

static inline uint32_t Rotr(uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

/* one 64-byte block */
static void Compress(uint32_t h[8], const unsigned char b[64])
{
  uint32_t w[64], a, bb, c, d, e, f, g, hh;

  for (int t = 0; t < 16; t++) w[t] = (uint32_t)b[4 * t] << 24 | (uint32_t)b[4 * t + 1] << 16 | (uint32_t)b[4 * t + 2] << 8 | (uint32_t)b[4 * t + 3];
  for (int t = 16; t < 64; t++) {
    const uint32_t s0 = Rotr(w[t - 15], 7) ^ Rotr(w[t - 15], 18) ^ (w[t - 15] >> 3);
    const uint32_t s1 = Rotr(w[t - 2], 17) ^ Rotr(w[t - 2], 19) ^ (w[t - 2] >> 10);
    w[t]              = w[t - 16] + s0 + w[t - 7] + s1;
  }
  a  = h[0];
  bb = h[1];
  c  = h[2];
  d  = h[3];
  e  = h[4];
  f  = h[5];
  g  = h[6];
  hh = h[7];
  for (int t = 0; t < 64; t++) {
    const uint32_t S1 = Rotr(e, 6) ^ Rotr(e, 11) ^ Rotr(e, 25);
    const uint32_t ch = (e & f) ^ (~e & g);
    const uint32_t t1 = hh + S1 + ch + K[t] + w[t];
    const uint32_t S0 = Rotr(a, 2) ^ Rotr(a, 13) ^ Rotr(a, 22);
    const uint32_t mj = (a & bb) ^ (a & c) ^ (bb & c);
    const uint32_t t2 = S0 + mj;
    hh                = g;
    g                 = f;
    f                 = e;
    e                 = d + t1;
    d                 = c;
    c                 = bb;
    bb                = a;
    a                 = t1 + t2;
  }
  h[0] += a;
  h[1] += bb;
  h[2] += c;
  h[3] += d;
  h[4] += e;
  h[5] += f;
  h[6] += g;
  h[7] += hh;
}

void HylcSha256Init(HylcSha256 *s)
{
  static const uint32_t H0[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  memcpy(s->h, H0, sizeof(H0));
  s->nbytes = 0;
  s->nbuf   = 0;
}

void HylcSha256Update(HylcSha256 *s, const void *data, size_t n)
{
  const unsigned char *p = (const unsigned char *)data;

  s->nbytes += n;
  if (s->nbuf) {
    size_t k = 64 - s->nbuf < n ? 64 - s->nbuf : n;
    memcpy(s->buf + s->nbuf, p, k);
    s->nbuf += k;
    p += k;
    n -= k;
    if (s->nbuf < 64) return;
    Compress(s->h, s->buf);
    s->nbuf = 0;
  }
  for (; n >= 64; p += 64, n -= 64) Compress(s->h, p);
  memcpy(s->buf, p, n);
  s->nbuf = n;
}

void HylcSha256Final(HylcSha256 *s, unsigned char digest[32])
{
  const uint64_t bits = s->nbytes * 8;

  s->buf[s->nbuf++] = 0x80;
  if (s->nbuf > 56) {
    memset(s->buf + s->nbuf, 0, 64 - s->nbuf);
    Compress(s->h, s->buf);
    s->nbuf = 0;
  }
  memset(s->buf + s->nbuf, 0, 56 - s->nbuf);
  for (int i = 0; i < 8; i++) s->buf[56 + i] = (unsigned char)(bits >> (56 - 8 * i));
  Compress(s->h, s->buf);
  for (int i = 0; i < 8; i++)
    for (int k = 0; k < 4; k++) digest[4 * i + k] = (unsigned char)(s->h[i] >> (24 - 8 * k));
  memset(s, 0, sizeof(*s));
}

void HylcSha256ToHex(const unsigned char digest[32], char hex[65])
{
  static const char X[] = "0123456789abcdef";
  for (int i = 0; i < 32; i++) {
    hex[2 * i]     = X[digest[i] >> 4];
    hex[2 * i + 1] = X[digest[i] & 15];
  }
  hex[64] = 0;
}

void HylcSha256Hex(const void *data, size_t n, char hex[65])
{
  HylcSha256    s;
  unsigned char d[32];

  HylcSha256Init(&s);
  HylcSha256Update(&s, data, n);
  HylcSha256Final(&s, d);
  HylcSha256ToHex(d, hex);
}
