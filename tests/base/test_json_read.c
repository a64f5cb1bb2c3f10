/* Unit tests of base/json_read (the bench part-file reader): a document
 * reads back with exact numbers and decoded strings; every malformed input
 * is refused with a message naming the file and the byte. */
#include "json_read.h"
#include "test.h"

#include <stdio.h>
#include <string.h>

static bool parse(const char* text, tv_json* j, char* err, size_t size)
{
    return tv_json_parse(text, strlen(text), "t.json", j, err, size);
}

static void reads_a_document(void)
{
    char err[256], text[512];
    const double x = 0.1 + 0.2; /* not representable in few digits */
    snprintf(text, sizeof text,
             " {\"a\": [1, -2.5e3, %.17g], \"s\": \"q\\\"\\\\\\n\\u0041\\u00e9\", \"o\": {\"t\": true, \"n\": null}, "
             "\"e\": [], \"f\": false} ",
             x);
    tv_json j;
    TV_CHECK(parse(text, &j, err, sizeof err));
    const tv_json* a = tv_json_get(&j, "a");
    TV_CHECK(a && a->type == TV_JSON_ARRAY && a->count == 3);
    TV_CHECK(a && a->items[1].num == -2500.0 && a->items[2].num == x);
    const tv_json* s = tv_json_get(&j, "s");
    TV_CHECK(s && s->type == TV_JSON_STRING && strcmp(s->str, "q\"\\\nA?") == 0);
    const tv_json* o = tv_json_get(&j, "o");
    TV_CHECK(o && tv_json_get(o, "t")->type == TV_JSON_BOOL && tv_json_get(o, "t")->num == 1.0);
    TV_CHECK(o && tv_json_get(o, "n")->type == TV_JSON_NULL);
    TV_CHECK(tv_json_get(&j, "e")->count == 0 && tv_json_get(&j, "f")->num == 0.0);
    TV_CHECK(tv_json_get(&j, "missing") == NULL && tv_json_get(a, "a") == NULL);
    tv_json_free(&j);
}

static void refuses_bad_input(void)
{
    const char* bad[] = {"",          "{",          "{\"a\" 1}",   "{\"a\": 1,}", "[1 2]",    "[1] x",
                         "\"abc",     "\"a\\q\"",   "\"\\u12\"",   "-",           "1e",       "{1: 2}",
                         "[tru]",     "\"a\tb\"",   "{\"a\": [1, {\"b\": }]}",
                         /* a quote inside \u's four digits must not end the string early */
                         "[\"\\u12\"4abcdefghijklmnopqrstuvwxyz\"]"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char err[256] = "";
        tv_json j;
        bool ok = parse(bad[i], &j, err, sizeof err);
        TV_CHECK(!ok);
        TV_CHECK(strncmp(err, "t.json: byte ", 13) == 0);
        if (ok)
            tv_json_free(&j);
    }
    char deep[200];
    memset(deep, '[', 100);
    memset(deep + 100, ']', 99);
    deep[199] = 0;
    char err[256];
    tv_json j;
    TV_CHECK(!parse(deep, &j, err, sizeof err) && strstr(err, "nested too deeply"));
}

int main(void)
{
    TV_TEST_RUN(reads_a_document);
    TV_TEST_RUN(refuses_bad_input);
    return tv_test_finish();
}
