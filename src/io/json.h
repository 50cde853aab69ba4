/* A minimal JSON object writer for summary.json and benchmark output: one
 * flat object of numbers, integers, booleans and strings, keys in order. */
#ifndef NSPD_IO_JSON_H
#define NSPD_IO_JSON_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

typedef struct {
    FILE *out;
    int count;
} JsonWriter;

void json_begin(JsonWriter *w, FILE *out);
void json_number(JsonWriter *w, const char *key, double value); /* non-finite -> null */
void json_int(JsonWriter *w, const char *key, int64_t value);
void json_bool(JsonWriter *w, const char *key, bool value);
void json_string(JsonWriter *w, const char *key, const char *value);
void json_end(JsonWriter *w);

#endif
