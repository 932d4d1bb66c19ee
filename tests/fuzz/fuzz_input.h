/* Reading a fuzz target's input as a stream of fields: each take reads the
 * next bytes, and bytes past the end of the input read as 0, so that every
 * input decodes to something (libFuzzer's mutations then explore values, not
 * lengths). Shared by the C targets. */
#ifndef POLYMASS_FUZZ_INPUT_H
#define POLYMASS_FUZZ_INPUT_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef struct reader {
    const uint8_t* data;
    size_t size;
    size_t at;
} reader;

/* Copies n bytes to out; past the end of the input they are 0. */
static inline void take(reader* r, void* out, size_t n) {
    size_t have = r->at < r->size ? r->size - r->at : 0;
    if (have > n) have = n;
    if (have) memcpy(out, r->data + r->at, have);
    memset((uint8_t*)out + have, 0, n - have);
    r->at += n;
}

static inline uint8_t take_u8(reader* r) {
    uint8_t value;
    take(r, &value, 1);
    return value;
}

static inline double take_double(reader* r) {
    double value;
    take(r, &value, sizeof value);
    return value;
}

#endif /* POLYMASS_FUZZ_INPUT_H */
