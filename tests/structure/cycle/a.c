#include "a.h"
#include "b.h"
int pg_a(int x) { return x > 0 ? pg_b(x - 1) : 0; }
