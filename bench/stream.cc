// Memory bandwidth of one core, STREAM style (McCalpin's four kernels on
// arrays far larger than the caches), for the traffic model of the automata
// kernel (doc/performance.md, issue #48 item 1): how many bytes per second a
// core can move when nothing stays in cache. Counted as STREAM counts: copy
// and scale move 16 B per element, add and triad 24 B (the write-allocate
// read of the destination not counted; with it, x 1.5 and x 4/3).
//
//   g++ -O3 -march=native -o /tmp/stream bench/stream.cc && /tmp/stream
//   (two copies at once, `/tmp/stream & /tmp/stream; wait`: both cores)
//
// Prints the best of 10 repetitions of each kernel in GB/s (10^9 B/s).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

int
main(int argc, char **argv)
{
  // 3 x 80 MB: 7.5 times this machine's 32 MiB L3
  const std::size_t   n = argc > 1 ? std::atol(argv[1]) : 10000000;
  std::vector<double> a(n, 1.0), b(n, 2.0), c(n, 0.0);
  const double        s = 3.0;
  using Clock           = std::chrono::steady_clock;
  const char  *names[4] = {"copy", "scale", "add", "triad"};
  const double bytes[4] = {16.0 * n, 16.0 * n, 24.0 * n, 24.0 * n};
  double       best[4]  = {1e30, 1e30, 1e30, 1e30};
  for (int repeat = 0; repeat < 10; ++repeat)
    for (int k = 0; k < 4; ++k)
      {
        const auto start = Clock::now();
        switch (k)
          {
            case 0:
              for (std::size_t i = 0; i < n; ++i)
                c[i] = a[i];
              break;
            case 1:
              for (std::size_t i = 0; i < n; ++i)
                b[i] = s * c[i];
              break;
            case 2:
              for (std::size_t i = 0; i < n; ++i)
                c[i] = a[i] + b[i];
              break;
            default:
              for (std::size_t i = 0; i < n; ++i)
                a[i] = b[i] + s * c[i];
          }
        best[k] = std::min(
          best[k], std::chrono::duration<double>(Clock::now() - start).count());
      }
  for (int k = 0; k < 4; ++k)
    std::printf("%-6s %7.2f GB/s\n", names[k], bytes[k] / best[k] * 1e-9);
  // (keeps the loops from being optimized away)
  return a[n / 2] == 0.0 ? 1 : 0;
}
