#include "text_io.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool pred_text_fail(char* err, size_t err_size, const char* file, size_t line, const char* fmt, ...)
{
    char msg[512];
    va_list args;
    va_start(args, fmt);
    vsnprintf(msg, sizeof msg, fmt, args);
    va_end(args);
    if (err && err_size) {
        if (line)
            snprintf(err, err_size, "%s:%zu: %s", file, line, msg);
        else
            snprintf(err, err_size, "%s: %s", file, msg);
    }
    return false;
}

char* pred_text_read_file(const char* file, size_t* size, char* err, size_t err_size)
{
    FILE* f = fopen(file, "rb");
    if (!f) {
        pred_text_fail(err, err_size, file, 0, "cannot open (%s)", strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, n = 0, got;
    char* buf = malloc(cap + 1);
    while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap) {
            cap *= 2;
            char* grown = realloc(buf, cap + 1);
            if (!grown)
                free(buf);
            buf = grown;
        }
    }
    int read_error = ferror(f) ? errno : 0; /* EISDIR: a folder given as the file */
    fclose(f);
    if (!buf) {
        pred_text_fail(err, err_size, file, 0, "out of memory");
        return NULL;
    }
    if (read_error || memchr(buf, '\0', n)) {
        free(buf);
        if (read_error)
            pred_text_fail(err, err_size, file, 0, "read error (%s)", strerror(read_error));
        else
            pred_text_fail(err, err_size, file, 0, "binary data (NUL byte) in a text file");
        return NULL;
    }
    buf[n] = '\0';
    *size = n;
    return buf;
}

char* pred_text_trim(char* s)
{
    while (*s && isspace((unsigned char)*s))
        s++;
    size_t n = strlen(s);
    while (n && isspace((unsigned char)s[n - 1]))
        s[--n] = '\0';
    return s;
}

int pred_text_split(char* line, char** fields, int max_fields)
{
    int n = 0;
    for (char* tok = line;; n++) {
        char* comma = strchr(tok, ',');
        if (comma)
            *comma = '\0';
        if (n < max_fields)
            fields[n] = pred_text_trim(tok);
        if (!comma)
            return n + 1;
        tok = comma + 1;
    }
}

char* pred_text_next_line(char** cursor)
{
    char* line = *cursor;
    if (!line || !*line)
        return NULL;
    char* nl = strchr(line, '\n');
    if (nl)
        *nl++ = '\0';
    *cursor = nl;
    return line;
}
