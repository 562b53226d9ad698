// The main of the core benchmarks: the applications' memory policy (keepFreedMemoryForReruns: a
// re-run reuses the memory the run before freed), then Google Benchmark's own main.
#include "nav/BulkAllocator.h"

#include <benchmark/benchmark.h>

int main(int argc, char** argv)
{
    footpath::keepFreedMemoryForReruns();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
