/* file_io.c — see file_io.h. POSIX (open, fsync, rename) for the atomic write. */
#define _POSIX_C_SOURCE 200809L
#include "file_io.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int desktop_read_file(const char *path, uint8_t **data, size_t *size, char *error, size_t error_capacity)
{
    FILE *f = fopen(path, "rb");
    uint8_t *buf = NULL;
    size_t len = 0, cap = 0, got;
    *data = NULL;
    *size = 0;
    if (f == NULL) {
        snprintf(error, error_capacity, "cannot open %s: %s", path, strerror(errno));
        return 0;
    }
    for (;;) {
        if (cap - len < 65536u) {
            size_t ncap = cap != 0 ? cap * 2u : 65536u;
            uint8_t *nbuf = (uint8_t *)realloc(buf, ncap + 1u);
            if (nbuf == NULL) {
                snprintf(error, error_capacity, "out of memory reading %s", path);
                free(buf);
                fclose(f);
                return 0;
            }
            buf = nbuf;
            cap = ncap;
        }
        got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0) break;
    }
    if (ferror(f)) {
        snprintf(error, error_capacity, "cannot read %s: %s", path, strerror(errno));
        free(buf);
        fclose(f);
        return 0;
    }
    fclose(f);
    buf[len] = 0;
    *data = buf;
    *size = len;
    return 1;
}

int desktop_write_file_atomic(const char *path, const uint8_t *data, size_t size, char *error, size_t error_capacity)
{
    size_t n = strlen(path), done = 0;
    char *tmp = (char *)malloc(n + 5u);
    int fd;
    if (tmp == NULL) {
        snprintf(error, error_capacity, "out of memory");
        return 0;
    }
    memcpy(tmp, path, n);
    memcpy(tmp + n, ".tmp", 5u);
    fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) {
        snprintf(error, error_capacity, "cannot create %s: %s", tmp, strerror(errno));
        free(tmp);
        return 0;
    }
    while (done < size) {
        ssize_t w = write(fd, data + done, size - done);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) {
            snprintf(error, error_capacity, "cannot write %s: %s", tmp, strerror(errno));
            close(fd);
            unlink(tmp);
            free(tmp);
            return 0;
        }
        done += (size_t)w;
    }
    if (fsync(fd) != 0 || close(fd) != 0) {
        snprintf(error, error_capacity, "cannot flush %s: %s", tmp, strerror(errno));
        unlink(tmp);
        free(tmp);
        return 0;
    }
    if (rename(tmp, path) != 0) {
        snprintf(error, error_capacity, "cannot rename %s to %s: %s", tmp, path, strerror(errno));
        unlink(tmp);
        free(tmp);
        return 0;
    }
    free(tmp);
    return 1;
}
