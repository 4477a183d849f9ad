/* SHA-256 from nettle (include/hylc/sha256.h): hylc's names over sha256_init/update/digest. */
#include <hylc/sha256.h>

void HylcSha256Init(HylcSha256 *s) { sha256_init(&s->ctx); }

void HylcSha256Update(HylcSha256 *s, const void *data, size_t n)
{
  if (n) sha256_update(&s->ctx, n, (const uint8_t *)data);
}

void HylcSha256Final(HylcSha256 *s, unsigned char digest[32]) { sha256_digest(&s->ctx, SHA256_DIGEST_SIZE, digest); }

void HylcSha256ToHex(const unsigned char digest[32], char hex[65])
{
  static const char xd[] = "0123456789abcdef";
  for (int i = 0; i < 32; i++) {
    hex[2 * i]     = xd[digest[i] >> 4];
    hex[2 * i + 1] = xd[digest[i] & 15];
  }
  hex[64] = '\0';
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
