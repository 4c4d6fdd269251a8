// How the memory bandwidth of one core depends on the number of arrays a loop reads at once
// (Documentation/CacheCliff.md). A structure of arrays makes a pass that needs k quantities per
// particle read k arrays side by side, and on some machines the bandwidth falls with k while the
// same bytes in one array of k-value records do not (measurements: Documentation/CacheCliff.md,
// "Why"). It measures both on the machine at hand, so that a layout decision rests on numbers
// from it.
//
//   MemoryStreams [megabytes per array, default 16] [repeats, default 3]
//
// Each row: k arrays of n 8-byte integers read in step (element i of every array, then i + 1),
// and one array of n records of k integers read in order; the same bytes, the fastest of the
// repeats. (Integer sums: one cycle per add, so that the loop waits on memory, not on its adds.)
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "WholeArgument.h"

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

int main(int argc, char** argv) {
    const long megabytes = wholeArgument(argc, argv, 1, 16, 1, 4096, "MemoryStreams", "megabytes per array (argument 1)");
    const long repeats = wholeArgument(argc, argv, 2, 3, 1, 4096, "MemoryStreams", "repeats (argument 2)");
    // (Not a power of two, so that the arrays do not line up on the same cache sets.)
    const std::size_t n = static_cast<std::size_t>(megabytes) * (1 << 20) / 8 - 1237;
    const int counts[] = {1, 2, 4, 8, 12, 16, 24, 32};
    const int mostArrays = 32;
    std::vector<std::vector<std::uint64_t>> arrays(mostArrays, std::vector<std::uint64_t>(n, 1));
    std::vector<std::uint64_t> records(n * mostArrays, 1);
    std::printf("MemoryStreams: %ld MB per array, fastest of %ld\n", megabytes, repeats);
    std::printf("%7s %22s %26s %8s\n", "arrays", "separate arrays GB/s", "one array of records GB/s", "ratio");
    std::uint64_t check = 0;
    for (const int k : counts) {
        double separate = 1e300, interleaved = 1e300;
        std::vector<const std::uint64_t*> at(k);
        for (int a = 0; a < k; ++a) at[a] = arrays[a].data();
        for (long r = 0; r < repeats; ++r) {
            std::uint64_t sum = 0;
            Clock::time_point start = Clock::now();
            for (std::size_t i = 0; i < n; ++i)
                for (int a = 0; a < k; ++a) sum += at[a][i];
            separate = std::min(separate, secondsSince(start));
            start = Clock::now();
            const std::uint64_t* record = records.data();
            for (std::size_t i = 0; i < n * k; ++i) sum += record[i];
            interleaved = std::min(interleaved, secondsSince(start));
            check += sum;
        }
        const double bytes = 8.0 * n * k;
        std::printf("%7d %22.2f %26.2f %8.2f\n", k, bytes / separate * 1e-9, bytes / interleaved * 1e-9,
                    separate / interleaved);
    }
    // (Every element is 1: the sums are known, and printing them keeps the loops from being
    // dropped.)
    const std::uint64_t expected = static_cast<std::uint64_t>(repeats) * 2 * n * (1 + 2 + 4 + 8 + 12 + 16 + 24 + 32);
    std::printf("MemoryStreams: %s (sum %llu)\n", check == expected ? "done" : "WRONG SUM",
                static_cast<unsigned long long>(check));
    return check == expected ? 0 : 1;
}
