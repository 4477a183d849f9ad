#pragma once
/* SHA-256 (FIPS 180-4) of nettle (libnettle, Debian nettle-dev; every hylc program already loads it
   through PETSc's and HDF5's dependencies): the digest of a run's identity (the sampler's resume
   fingerprint, docs/output-format.md). These wrappers keep hylc's names and its hexadecimal form; the
   digests are those of any SHA-256 (tests/unit/test_sha256.c checks the published FIPS 180 vectors,
   tests/regression/sampler_identity.sh compares with Python's hashlib). Not thread-safe per context; no
   global state, no allocation. */
#include <stddef.h>
#include <nettle/sha2.h>

typedef struct {
  struct sha256_ctx ctx;
} HylcSha256;

void HylcSha256Init(HylcSha256 *);
void HylcSha256Update(HylcSha256 *, const void *, size_t);
/* the 32-byte digest; the context is reset to HylcSha256Init's state */
void HylcSha256Final(HylcSha256 *, unsigned char digest[32]);
/* the digest of n bytes as 64 lower-case hexadecimal digits and a terminating NUL */
void HylcSha256Hex(const void *, size_t, char hex[65]);
/* 32 raw bytes as 64 hexadecimal digits and a NUL */
void HylcSha256ToHex(const unsigned char digest[32], char hex[65]);
