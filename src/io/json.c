#include "io/json.h"

#include <math.h>

static void key(JsonWriter *w, const char *k) {
    fprintf(w->out, "%s\n  \"%s\": ", w->count++ ? "," : "", k);
}

void json_begin(JsonWriter *w, FILE *out) {
    w->out = out;
    w->count = 0;
    fputc('{', out);
}

void json_number(JsonWriter *w, const char *k, double value) {
    key(w, k);
    if (isfinite(value))
        fprintf(w->out, "%.10g", value);
    else
        fputs("null", w->out);
}

void json_int(JsonWriter *w, const char *k, int64_t value) {
    key(w, k);
    fprintf(w->out, "%lld", (long long)value);
}

void json_bool(JsonWriter *w, const char *k, bool value) {
    key(w, k);
    fputs(value ? "true" : "false", w->out);
}

void json_string(JsonWriter *w, const char *k, const char *value) {
    key(w, k);
    fputc('"', w->out);
    for (const char *p = value; *p; p++) {
        if (*p == '"' || *p == '\\')
            fprintf(w->out, "\\%c", *p);
        else if ((unsigned char)*p < 0x20)
            fprintf(w->out, "\\u%04x", *p);
        else
            fputc(*p, w->out);
    }
    fputc('"', w->out);
}

void json_end(JsonWriter *w) {
    fputs(w->count ? "\n}\n" : "}\n", w->out);
}
