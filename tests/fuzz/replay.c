/* SPDX-License-Identifier: BSD-3-Clause */
/* Runs a fuzz harness's LLVMFuzzerTestOneInput on files, without libFuzzer: `make check`
 * replays the committed corpus and crash reproducers this way, in the sanitizer build.
 * Arguments: files or directories (every file in them). */
#define _DEFAULT_SOURCE /* scandir, alphasort */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "replay: cannot open %s\n", path);
        return 1;
    }
    fseek(f, 0, SEEK_END);
    const long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    uint8_t *data = malloc(size > 0 ? (size_t)size : 1);
    const size_t got = fread(data, 1, (size_t)(size > 0 ? size : 0), f);
    fclose(f);
    LLVMFuzzerTestOneInput(data, got);
    free(data);
    return 0;
}

int main(int argc, char **argv)
{
    int inputs = 0, failures = 0;
    for (int i = 1; i < argc; ++i) {
        struct stat st;
        if (stat(argv[i], &st) != 0) {
            fprintf(stderr, "replay: no such file or directory: %s\n", argv[i]);
            return 1;
        }
        if (!S_ISDIR(st.st_mode)) {
            failures += run_file(argv[i]);
            ++inputs;
            continue;
        }
        struct dirent **entries;
        const int n = scandir(argv[i], &entries, NULL, alphasort); /* a fixed order */
        for (int k = 0; k < n; ++k) {
            if (entries[k]->d_name[0] != '.') {
                char path[4096];
                snprintf(path, sizeof path, "%s/%s", argv[i], entries[k]->d_name);
                failures += run_file(path);
                ++inputs;
            }
            free(entries[k]);
        }
        free(entries);
    }
    /* In the form scripts/run-tests.sh counts: an input that broke the contract aborted. */
    printf("replay: %d passed, %d failed\n", inputs - failures, failures);
    return failures != 0;
}
