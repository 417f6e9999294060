int pg_b(int x);
