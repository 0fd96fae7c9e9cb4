// Isa: the instruction sets rayvec has kernels for, and the cpuid probe that picks one at run time.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rayvec {

// Ordered from least to most capable. Each has its own translation units (*_avx2.cpp, *_avx512.cpp)
// compiled with its own flags; `scalar` is plain baseline x86-64 code.
enum class Isa { scalar = 0, avx2 = 1, avx512 = 2 };

inline constexpr Isa kAllIsas[] = {Isa::scalar, Isa::avx2, Isa::avx512};

struct CpuFeatures {
  std::string vendor;
  std::string brand;
  bool sse2 = false, avx = false, avx2 = false, fma = false, bmi2 = false;
  bool avx512f = false, avx512dq = false, avx512bw = false, avx512vl = false, avx512cd = false;
  bool os_ymm = false;  // XCR0: the OS saves YMM state
  bool os_zmm = false;  // XCR0: the OS saves opmask and ZMM state
};

// Read once (cpuid + xgetbv) and cached.
const CpuFeatures& cpu_features();

// True when this CPU and OS can run the ISA's kernels.
bool isa_supported(Isa isa);
// The most capable supported ISA.
Isa best_isa();
// Every supported ISA, scalar first.
std::vector<Isa> supported_isas();

const char* isa_name(Isa isa);
// "scalar" | "avx2" | "avx512"; nullopt for anything else ("auto" is handled by resolve_isa).
std::optional<Isa> parse_isa(std::string_view name);

// Resolves a user's --isa value: "auto" gives best_isa(); a named ISA must be supported.
// Returns an error message (empty on success) so callers can report it as bad usage.
std::string resolve_isa(std::string_view name, Isa& out);

}  // namespace rayvec
