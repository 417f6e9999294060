int pg_a(int x);
int pg_a(int x) { return x; }
