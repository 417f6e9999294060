/* file_io.h — whole-file reads and crash-safe whole-file writes for the desktop port. */
#ifndef DESKTOP_FILE_IO_H
#define DESKTOP_FILE_IO_H

#include <stddef.h>
#include <stdint.h>

/* Read all of `path` into a malloc'd buffer (NUL-terminated one byte past *size).
 * Returns 0 and a sentence in `error` on failure. */
int desktop_read_file(const char *path, uint8_t **data, size_t *size, char *error, size_t error_capacity);

/* Write `data` to PATH.tmp, flush it to disk and rename it over `path`, so that a kill
 * or a crash at any moment leaves either the previous file or the new one, whole. */
int desktop_write_file_atomic(const char *path, const uint8_t *data, size_t size, char *error, size_t error_capacity);

#endif
