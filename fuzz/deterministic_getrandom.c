/* Preloaded by `scripts/fuzz.sh --ci` only (docs/robustness.md): getrandom(2) filling the
 * buffer with a fixed byte stream, so that the random keys of Rust std's HashMap
 * (RandomState, read once per thread with getrandom) are the same in every run. With random
 * keys a table's probe sequences, and so the coverage libFuzzer steers by, differ from process
 * to process: the same -seed then tries other inputs. Nothing else in the fuzz processes draws
 * from getrandom (libFuzzer's own generator is seeded by -seed). */
#include <stddef.h>
#include <sys/types.h>

ssize_t getrandom(void *buf, size_t len, unsigned int flags) {
    (void)flags;
    unsigned char *out = buf;
    for (size_t i = 0; i < len; i++)
        out[i] = (unsigned char)(0x5a ^ i);
    return (ssize_t)len;
}
