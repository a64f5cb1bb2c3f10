/* text_io.h - the small text-file helpers the predict/ readers share (path
 * CSV, recorded-trace importers): whole-file reading, "FILE:LINE: problem"
 * errors, whitespace trimming and in-place comma splitting. Internal to
 * predict/. */
#ifndef TRIMVR_PRED_TEXT_IO_H
#define TRIMVR_PRED_TEXT_IO_H

#include <stdbool.h>
#include <stddef.h>

/* Writes "FILE:LINE: message" (or "FILE: message" when line is 0) into err
 * (may be NULL) and returns false, so readers can `return pred_text_fail(...)`. */
#if defined(__GNUC__)
__attribute__((format(printf, 5, 6)))
#endif
bool pred_text_fail(char* err, size_t err_size, const char* file, size_t line, const char* fmt, ...);

/* The whole file, NUL-terminated and malloc'ed (caller frees), its length
 * in *size. NULL with the error in err when it cannot be read or holds a NUL
 * byte (binary data is never a text format we read). */
char* pred_text_read_file(const char* file, size_t* size, char* err, size_t err_size);

/* Leading and trailing whitespace (CR of CRLF files included) removed in place. */
char* pred_text_trim(char* s);

/* Splits a line at commas in place into at most max_fields trimmed fields;
 * returns the number of fields the line has (may exceed max_fields, in which
 * case only the first max_fields are stored). */
int pred_text_split(char* line, char** fields, int max_fields);

/* Iterates over the lines of a NUL-terminated buffer in place: returns the
 * next line (its '\n' replaced by NUL) and advances *cursor, or NULL at the
 * end. *cursor is NULL after a last line without '\n': a file cut short ends
 * so, and its last field may then be a cut number that still parses. */
char* pred_text_next_line(char** cursor);

#endif
