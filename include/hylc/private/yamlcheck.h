#pragma once
/* The check of a YAML options file before PetscInitialize() (src/sys/yamlcheck.c): parsed by libyaml, the
   parser PETSc itself reads YAML options files with, so that a malformed file is reported as
   "file:line:column: problem" instead of PETSc's "YAML parser loading error" (which names neither), and
   the structure PETSc's reader takes checked too: the top level a mapping, every key an option name
   (letters, digits, '_', '-', '.'; YAML's merge key "<<"), values scalars, lists or nested mappings, and
   no key without a value ("key:" alone is YAML's null, which PETSc would take as the option's default).
   Plain C, no PETSc (MPI is not initialized yet). Returns 0, or writes one line to msg and returns 1. */
#include <stddef.h>

int HylcYAMLCheckFile(const char path[], char msg[], size_t len);
