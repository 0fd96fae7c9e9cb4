// `rayvec info` names, for every ISA this CPU supports, the choices rayvec makes by CPU vendor, so a
// benchmark row can be traced to the kernels that produced it.
#include <gtest/gtest.h>

#include <string>

#include "kernels/triangle_kernels.h"
#include "platform/isa.h"
#include "test_support.h"

namespace rayvec {
namespace {

TEST(InfoCli, NamesTheMtPretestOfEverySupportedIsa) {
  const auto r = test::run_cli("info");
  ASSERT_EQ(r.status, 0) << r.err;
  for (Isa isa : kAllIsas) {
    const std::string head = std::string("  ") + isa_name(isa);
    const std::size_t at = r.out.find(head + " ");
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
    if (!isa_supported(isa)) {
      EXPECT_NE(line.find("not supported"), std::string::npos) << line;
      continue;
    }
    const std::string pretest = mt_pretest_name(default_mt_pretest(isa, cpu_features().vendor));
    EXPECT_NE(line.find("mt pre-test: " + pretest), std::string::npos) << line;
  }
}

}  // namespace
}  // namespace rayvec
