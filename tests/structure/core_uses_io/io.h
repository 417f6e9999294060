int pg_io(int x);
