/* YAML options files checked with libyaml before PetscInitialize() (include/hylc/private/yamlcheck.h). */
#include <hylc/private/yamlcheck.h>
#include <yaml.h>
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#define HYLC_YAML_DEPTH 64

typedef struct {
  int map;      /* 1 a mapping, 0 a sequence */
  int want_key; /* in a mapping: the next node is a key */
} Frame;

static const char *NodeKind(yaml_event_type_t t) { return t == YAML_MAPPING_START_EVENT ? "a mapping" : t == YAML_SEQUENCE_START_EVENT ? "a list" : t == YAML_ALIAS_EVENT ? "an alias" : "a value"; }

static int ValidName(const char *s, size_t n)
{
  if (n == 2 && !strncmp(s, "<<", 2)) return 1; /* the merge key, which PETSc's reader follows */
  if (!n) return 0;
  for (size_t i = 0; i < n; i++)
    if (!(isalnum((unsigned char)s[i]) || s[i] == '_' || s[i] == '-' || s[i] == '.')) return 0;
  return 1;
}

/* the parser's own message: where it was (the context, e.g. "while scanning a quoted scalar", starts
   on the line at fault) and what it found */
static void ParserMessage(const char path[], const yaml_parser_t *p, char msg[], size_t len)
{
  const char *problem = p->problem ? p->problem : "malformed YAML";
  if (p->context)
    snprintf(msg, len, "%s:%zu:%zu: %s: %s (at line %zu, column %zu)", path, p->context_mark.line + 1, p->context_mark.column + 1, p->context, problem, p->problem_mark.line + 1, p->problem_mark.column + 1);
  else
    snprintf(msg, len, "%s:%zu:%zu: %s", path, p->problem_mark.line + 1, p->problem_mark.column + 1, problem);
}

int HylcYAMLCheckFile(const char path[], char msg[], size_t len)
{
  FILE         *fp;
  struct stat   st;
  yaml_parser_t parser;
  yaml_event_t  ev;
  Frame         stack[HYLC_YAML_DEPTH];
  int           depth = 0, bad = 0, done = 0, root = 0;
  char          key[201] = "";

  if (stat(path, &st) != 0) return snprintf(msg, len, "Cannot open options file %s: %s", path, strerror(errno)), 1;
  if (S_ISDIR(st.st_mode)) return snprintf(msg, len, "Cannot read options file %s: it is a directory", path), 1;
  fp = fopen(path, "rb");
  if (!fp) return snprintf(msg, len, "Cannot open options file %s: %s", path, strerror(errno)), 1;
  if (!yaml_parser_initialize(&parser)) {
    fclose(fp);
    return snprintf(msg, len, "Cannot read options file %s: libyaml could not allocate its parser", path), 1;
  }
  yaml_parser_set_input_file(&parser, fp);
  while (!bad && !done) {
    if (!yaml_parser_parse(&parser, &ev)) {
      ParserMessage(path, &parser, msg, len);
      bad = 1;
      break;
    }
    const size_t      line = ev.start_mark.line + 1, col = ev.start_mark.column + 1;
    yaml_event_type_t t   = ev.type;
    Frame            *top = depth ? &stack[depth - 1] : NULL;

    switch (t) {
    case YAML_STREAM_END_EVENT:
      done = 1;
      break;
    case YAML_DOCUMENT_START_EVENT:
      root = 1;
      break;
    case YAML_MAPPING_START_EVENT:
    case YAML_SEQUENCE_START_EVENT:
    case YAML_SCALAR_EVENT:
    case YAML_ALIAS_EVENT:
      if (root) { /* the document's top node */
        root = 0;
        if (t == YAML_SCALAR_EVENT && ev.data.scalar.length == 0 && ev.data.scalar.style == YAML_PLAIN_SCALAR_STYLE) break; /* an empty document */
        if (t != YAML_MAPPING_START_EVENT) {
          snprintf(msg, len, "%s:%zu:%zu: the top level of an options file must be 'key: value' lines, found %s", path, line, col, NodeKind(t));
          bad = 1;
          break;
        }
      } else if (top && top->map && top->want_key) {
        if (t != YAML_SCALAR_EVENT) {
          snprintf(msg, len, "%s:%zu:%zu: an option name is expected before ':', found %s", path, line, col, NodeKind(t));
          bad = 1;
          break;
        }
        if (!ValidName((const char *)ev.data.scalar.value, ev.data.scalar.length)) {
          snprintf(msg, len, "%s:%zu:%zu: '%.*s' is not an option name (letters, digits, '_' only)", path, line, col, (int)(ev.data.scalar.length > 200 ? 200 : ev.data.scalar.length), (const char *)ev.data.scalar.value);
          bad = 1;
          break;
        }
        snprintf(key, sizeof(key), "%.*s", (int)(ev.data.scalar.length > 200 ? 200 : ev.data.scalar.length), (const char *)ev.data.scalar.value);
        top->want_key = 0;
        break;
      } else if (top && top->map) {
        /* this node is the value; a key comes next. "key:" with nothing after it is YAML's null, which
           PETSc's reader would take as an option without a value and the option's default */
        if (t == YAML_SCALAR_EVENT && ev.data.scalar.length == 0 && ev.data.scalar.style == YAML_PLAIN_SCALAR_STYLE) {
          snprintf(msg, len, "%s:%zu:%zu: '%s' has no value (give it one, or remove the line)", path, ev.start_mark.line + 1, ev.start_mark.column + 1, key);
          bad = 1;
          break;
        }
        top->want_key = 1;
      }
      if (t == YAML_MAPPING_START_EVENT || t == YAML_SEQUENCE_START_EVENT) {
        if (depth >= HYLC_YAML_DEPTH) {
          snprintf(msg, len, "%s:%zu:%zu: nested too deeply (more than %d levels)", path, line, col, HYLC_YAML_DEPTH);
          bad = 1;
          break;
        }
        stack[depth].map      = t == YAML_MAPPING_START_EVENT;
        stack[depth].want_key = 1;
        depth++;
      }
      break;
    case YAML_MAPPING_END_EVENT:
    case YAML_SEQUENCE_END_EVENT:
      if (depth) depth--;
      break;
    default:
      break;
    }
    yaml_event_delete(&ev);
  }
  if (!bad && ferror(fp)) {
    snprintf(msg, len, "Cannot read options file %s: %s", path, strerror(errno));
    bad = 1;
  }
  yaml_parser_delete(&parser);
  fclose(fp);
  return bad;
}
