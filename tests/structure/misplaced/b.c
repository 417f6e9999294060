#include "b.h"
int pg_b(int x) { return pg_a(x); }
