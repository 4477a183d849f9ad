#pragma once
/* SHA-256 (FIPS 180-4), plain C: the digest of a run's identity (the sampler's resume fingerprint,
   docs/output-format.md). Written for hylc; checked against the published test vectors in
   tests/unit/test_sha256.c. Not thread-safe per context; no global state. */
#include <stddef.h>
#include <stdint.h>

typedef struct {
  uint32_t      h[8];
  uint64_t      nbytes; /* message length so far */
  unsigned char buf[64];
  size_t        nbuf;
} HylcSha256;

void HylcSha256Init(HylcSha256 *);
void HylcSha256Update(HylcSha256 *, const void *, size_t);
void HylcSha256Final(HylcSha256 *, unsigned char digest[32]);
/* the digest of n bytes as 64 lower-case hexadecimal digits and a terminating NUL */
void HylcSha256Hex(const void *, size_t, char hex[65]);
/* 32 raw bytes as 64 hexadecimal digits and a NUL */
void HylcSha256ToHex(const unsigned char digest[32], char hex[65]);
