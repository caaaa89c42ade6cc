/// @file test_signature_header.cpp
/// The committed lib/include/hstmon/generated/thesis_signatures.hpp is what the generator
/// writes today, and it compiles as a constexpr table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "hstmon/generated/thesis_signatures.hpp"
#include "hstmon/thesis_reduced.hpp"
#include "hstmon_fdi/signature_table.hpp"

namespace hstmon::fdi {
namespace {

static_assert(kThesisSignatureCount == static_cast<int>(sizeof(kThesisSignatures) / sizeof(kThesisSignatures[0])));
static_assert(kThesisSignatures[0].channel[kChPpp].magnitude == kQualPlus, "kp- raises Ppp");

TEST(SignatureHeader, CommittedHeaderIsUpToDate) {
  const std::string path = std::string(HSTMON_SOURCE_DIR) + "/" + kSignatureHeaderPath;
  std::ifstream f(path, std::ios::binary);
  ASSERT_TRUE(f) << path;
  std::stringstream ss;
  ss << f.rdbuf();
  const SignatureOptions opt;
  EXPECT_EQ(ss.str(), render_signature_header(build_signature_rows(opt), opt))
      << "regenerate: thesis_signature_header " << kSignatureHeaderPath;
}

TEST(SignatureHeader, RowsFollowTheCatalogue) {
  const std::vector<SignatureRow> rows = build_signature_rows();
  ASSERT_EQ(static_cast<int>(rows.size()), kThesisSignatureCount);
  for (int i = 0; i < kThesisSignatureCount; ++i) {
    EXPECT_STREQ(rows[static_cast<std::size_t>(i)].sig.name, kThesisSignatures[i].name);
    float norm = 0.0f;
    for (float d : kThesisSignatures[i].direction) norm += d * d;
    // Unit vectors, or zero where the fault leaves the steady state alone (K, J, sensors).
    EXPECT_TRUE(std::abs(norm - 1.0f) < 1e-4f || norm == 0.0f) << kThesisSignatures[i].name;
  }
  // The thesis's blockage: kp- ⇒ Pmi+, Pmo−, Ppp+, ωm−, Ppp first (one integration).
  const FaultSignature& kp = kThesisSignatures[0];
  EXPECT_STREQ(kp.name, "kp-");
  EXPECT_EQ(kp.channel[kChPmi].magnitude, kQualPlus);
  EXPECT_EQ(kp.channel[kChPmo].magnitude, kQualMinus);
  EXPECT_EQ(kp.channel[kChWm].magnitude, kQualMinus);
  EXPECT_EQ(kp.channel[kChPpp].order, 1);
  const FaultSignature& s = kThesisSignatures[kThesisSignatureCount - 1];
  EXPECT_STREQ(s.name, "sensor_w_m");
  EXPECT_TRUE(s.sensor);
  EXPECT_EQ(s.channel[kChWm].magnitude, kQualAny);
  EXPECT_EQ(s.channel[kChPmi].magnitude, kQualZero);
}

TEST(SignatureHeader, OutputIsDeterministic) {
  const SignatureOptions opt;
  EXPECT_EQ(render_signature_header(build_signature_rows(opt), opt), render_signature_header(build_signature_rows(opt), opt));
}

}  // namespace
}  // namespace hstmon::fdi
