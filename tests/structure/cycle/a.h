int pg_a(int x);
