// Google Benchmark: what this machine gives two threads on work that shares nothing, the ceiling for solver.threads
// 2 (issue 35's goal: icosphere:6 on two threads at least 1.7x one). Compare items_per_second of /threads:2 with
// /threads:1 (real time): an FMA loop bound by the floating-point units (AVX2, 12 independent chains) and a
// read-modify-write pass over a buffer of each thread's own, 16 MiB (about the level-6 ball's vbd working set).
#include <benchmark/benchmark.h>

#include <immintrin.h>

#include <cstddef>
#include <vector>

namespace {

constexpr long kFmaRounds = 1 << 20;  // per iteration, kChains FMAs of 4 doubles each
constexpr int kChains = 12;           // enough independent chains to fill two FMA pipes of 4-cycle latency

__attribute__((target("avx2,fma"), noinline)) double fma_rounds(long rounds, double start) {
  __m256d chain[kChains];
  const __m256d factor = _mm256_set1_pd(0.999999), offset = _mm256_set1_pd(1e-7);
  for (int k = 0; k < kChains; ++k) chain[k] = _mm256_set1_pd(start + k);
  for (long r = 0; r < rounds; ++r) {
    for (int k = 0; k < kChains; ++k) chain[k] = _mm256_fmadd_pd(chain[k], factor, offset);
  }
  double lanes[4], sum = 0.0;
  for (int k = 0; k < kChains; ++k) {
    _mm256_storeu_pd(lanes, chain[k]);
    sum += lanes[0] + lanes[1] + lanes[2] + lanes[3];
  }
  return sum;
}

void BM_FmaThroughput(benchmark::State& st) {
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
    st.SkipWithError("this CPU has no AVX2 and FMA");
    return;
  }
  double start = 1.0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(start);  // each call's input unknown to the compiler: no call hoisted out of the loop
    benchmark::DoNotOptimize(fma_rounds(kFmaRounds, start));
  }
  st.SetItemsProcessed(st.iterations() * kFmaRounds * kChains * 4);  // double FMAs
}
BENCHMARK(BM_FmaThroughput)->Threads(1)->Threads(2)->UseRealTime();

void BM_OwnBufferPass(benchmark::State& st) {
  std::vector<double> buffer(std::size_t{16} << 20 >> 3, 1.0);  // 16 MiB of this thread's own
  for (auto _ : st) {
    double sum = 0.0;
    for (double& value : buffer) {
      value = value * 0.5 + 1.0;
      sum += value;
    }
    benchmark::DoNotOptimize(sum);
  }
  st.SetBytesProcessed(st.iterations() * static_cast<long>(buffer.size() * sizeof(double)));
}
BENCHMARK(BM_OwnBufferPass)->Threads(1)->Threads(2)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
