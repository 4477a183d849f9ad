#pragma once
/* A small strict JSON reader (RFC 8259) and Python's repr() of doubles (src/sys/json.c). Plain C99, no
   PETSc: compiled into libhylc and into libhylcmat, whose material schema (src/hylcmat/json.c) reads the
   tree. Errors are one line "file:line: what", written into the caller's buffer. */
#include <stddef.h>

#if defined(__GNUC__)
#  define HYLC_JSON_INTERN __attribute__((visibility("hidden")))
#else
#  define HYLC_JSON_INTERN
#endif

typedef enum { HYLC_JSON_NULL, HYLC_JSON_BOOL, HYLC_JSON_NUMBER, HYLC_JSON_STRING, HYLC_JSON_ARRAY, HYLC_JSON_OBJECT } HylcJsonType;

/* a value: its line in the text and, by type, the number, the string, or the items (and keys) */
typedef struct HylcJson {
  HylcJsonType     type;
  int              line;
  int              isint; /* a number written without fraction or exponent */
  double           num;   /* number; bool: 0 or 1 */
  char            *str;   /* string value */
  int              n, cap;
  struct HylcJson *items; /* array elements, object member values */
  char           **keys;  /* object member names */
} HylcJson;

enum {
  HYLC_JSON_OK         = 0,
  HYLC_JSON_ERR_SYNTAX = 1, /* not JSON (the message says where and why) */
  HYLC_JSON_ERR_MEMORY = 2
};

/* Parses the whole text (len bytes) of the file name into root, which the caller frees with
   HylcJsonFree(), also after an error. what names the expected document for the message on an empty
   file ("a JSON material"). Duplicate keys, trailing commas, NaN/Infinity, nesting deeper than 64 and
   text after the document are errors. Returns HYLC_JSON_OK or an error code with the message in err
   (errlen bytes, may be NULL). */
HYLC_JSON_INTERN int  HylcJsonParse(const char name[], const char what[], const char *text, size_t len, HylcJson *root, char *err, size_t errlen);
HYLC_JSON_INTERN void HylcJsonFree(HylcJson *);
/* the member key of an object, or NULL */
HYLC_JSON_INTERN const HylcJson *HylcJsonMember(const HylcJson *obj, const char key[]);
/* "null", "true/false", "a number", "a string", "an array", "an object" */
HYLC_JSON_INTERN const char *HylcJsonTypeName(HylcJsonType);
/* Python's repr() of a double (shortest round-trip digits: "1e-05", "200.0", "-0.0"; NaN, Infinity),
   what the JSON writers of the paper's tables write; buf needs 32 characters; returns buf */
HYLC_JSON_INTERN const char *HylcJsonFormatDouble(double x, char buf[32]);
