// The command-line numbers of the stand-alone measurement programs (MemoryStreams, LayoutProbe),
// which do not link the library and its CommandLine parser.
#pragma once

#include <cstdio>
#include <cstdlib>

// A whole number from argument `index` within [least, most], or `fallback` if it is absent;
// stops with a message naming the program and the argument if it is not one.
inline long wholeArgument(int argc, char** argv, int index, long fallback, long least, long most, const char* program,
                          const char* name) {
    if (argc <= index) return fallback;
    char* end = nullptr;
    const long value = std::strtol(argv[index], &end, 10);
    if (*argv[index] == '\0' || *end != '\0' || value < least || value > most) {
        std::fprintf(stderr, "%s: %s must be a whole number from %ld to %ld, got '%s'\n", program, name, least, most,
                     argv[index]);
        std::exit(2);
    }
    return value;
}
