/* SHA-256 (src/sys/sha256.c: nettle's, under hylc's names) against the published test vectors of FIPS 180-4 / NIST (the "abc", the
   empty message, the 448- and 896-bit messages, one million 'a'), and the same digest whatever the
   split of the input into updates.
   hylc-test: nprocs=1 */
#include <hylc/sha256.h>
#include <string.h>
#include "hylctest.h"

static void Check(const char *msg, size_t n, const char *want)
{
  char hex[65];
  HylcSha256Hex(msg, n, hex);
  HYLC_CHECK(!strcmp(hex, want), "sha256 of \"%.40s\" (%zu bytes) = %s, expected %s", msg, n, hex, want);
}

int main(void)
{
  static char   mil[1000000];
  const char   *m448 = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
  const char   *m896 = "abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmnopqrlmnopqrsmnopqrstnopqrstu";
  HylcSha256    s;
  unsigned char d[32];
  char          hex[65], ref[65];

  Check("abc", 3, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  Check("", 0, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  Check(m448, strlen(m448), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  Check(m896, strlen(m896), "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
  memset(mil, 'a', sizeof(mil));
  Check(mil, sizeof(mil), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  /* every split of the 896-bit message into two updates, and byte by byte, give the one-shot digest */
  HylcSha256Hex(m896, strlen(m896), ref);
  for (size_t k = 0; k <= strlen(m896); k++) {
    HylcSha256Init(&s);
    HylcSha256Update(&s, m896, k);
    HylcSha256Update(&s, m896 + k, strlen(m896) - k);
    HylcSha256Final(&s, d);
    HylcSha256ToHex(d, hex);
    HYLC_CHECK(!strcmp(hex, ref), "split at %zu: %s", k, hex);
  }
  HylcSha256Init(&s);
  for (size_t k = 0; k < 1000000; k++) HylcSha256Update(&s, "a", 1);
  HylcSha256Final(&s, d);
  HylcSha256ToHex(d, hex);
  HYLC_CHECK(!strcmp(hex, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"), "one million updates: %s", hex);
  /* lengths around the padding boundary (55, 56, 63, 64 bytes) against a byte-by-byte computation */
  for (size_t n = 54; n <= 66; n++) {
    HylcSha256Hex(mil, n, ref);
    HylcSha256Init(&s);
    for (size_t k = 0; k < n; k++) HylcSha256Update(&s, mil + k, 1);
    HylcSha256Final(&s, d);
    HylcSha256ToHex(d, hex);
    HYLC_CHECK(!strcmp(hex, ref), "length %zu", n);
  }
  Check(mil, 55, "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318");
  Check(mil, 56, "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a");
  Check(mil, 64, "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb");
  return hylc_test_failures ? 1 : 0;
}
