#include "io.h"
int pg_core(int x);
int pg_core(int x) { return pg_io(x); }
