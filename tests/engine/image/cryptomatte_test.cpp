// The Cryptomatte hash against published values: MurmurHash3_x86_32's
// reference vectors (SMHasher) and the manifest of the Cryptomatte
// specification 1.1.0; and the float conversion's promise that no id is
// zero, denormal, Inf or NaN.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <string>

#include "engine/image/cryptomatte.h"

namespace facet {
namespace {

TEST(MurmurHash3, MatchesTheReferenceVectors) {
  EXPECT_EQ(murmurHash3(""), 0u);
  EXPECT_EQ(murmurHash3("", 1), 0x514e28b7u);
  EXPECT_EQ(murmurHash3("hello"), 0x248bfa47u);
  EXPECT_EQ(murmurHash3("The quick brown fox jumps over the lazy dog"), 0x2e4ff723u);
}

TEST(Cryptomatte, IdsMatchTheSpecificationsManifest) {
  EXPECT_EQ(cryptomatteHex(cryptomatteId("bunny")), "13851a76");
  EXPECT_EQ(cryptomatteHex(cryptomatteId("default")), "42c9679f");
  EXPECT_EQ(cryptomatteHex(cryptomatteId("bunny_porcelain_mat")), "b24b26d4");
  EXPECT_EQ(nlohmann::json::parse(cryptomatteManifest({"bunny", "default", "bunny"})),
            nlohmann::json::parse(R"({"bunny": "13851a76", "default": "42c9679f"})"));
}

TEST(Cryptomatte, TheLayerKeyIsSevenHexDigitsOfItsNamesHash) {
  EXPECT_EQ(cryptomatteKey("CryptoObject"),
            cryptomatteHex(std::bit_cast<float>(murmurHash3("CryptoObject"))).substr(0, 7));
  EXPECT_EQ(cryptomatteKey("CryptoObject").size(), 7u);
  EXPECT_NE(cryptomatteKey("CryptoObject"), cryptomatteKey("CryptoMaterial"));
}

TEST(Cryptomatte, IdsAreNormalFloatsThatKeepEveryBitButTheClampedExponent) {
  int clamped = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::string name = "object " + std::to_string(i);
    const std::uint32_t hash = murmurHash3(name), bits = std::bit_cast<std::uint32_t>(cryptomatteId(name));
    ASSERT_TRUE(std::isnormal(cryptomatteId(name))) << name;
    EXPECT_EQ(bits & 0x807fffffu, hash & 0x807fffffu) << name;  // sign and mantissa
    const std::uint32_t exponent = (hash >> 23) & 0xffu;
    if (exponent == 0 || exponent == 255) {
      ++clamped;
      EXPECT_EQ((bits >> 23) & 0xffu, exponent == 0 ? 1u : 254u) << name;
    } else {
      EXPECT_EQ(bits, hash) << name;
    }
    ASSERT_EQ(cryptomatteId(name), cryptomatteId(std::string(name))) << "stable";
  }
  EXPECT_GT(clamped, 0) << "some of the names must reach the clamp (about 2 in 256)";
}

}  // namespace
}  // namespace facet
