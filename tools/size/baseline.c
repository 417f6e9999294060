/* baseline.c — a program with no pogon in it: its flash is subtracted from every
 * configuration's, so the size table counts what pogon adds (its code, its tables and
 * the libgcc helpers it calls), not the C library's start-up. The "core" and
 * "everything" configurations link this with every public function kept (-u). */
int main(void)
{
    return 0;
}
