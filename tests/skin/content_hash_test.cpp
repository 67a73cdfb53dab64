// FNV-1a 64 (skin/core/content_hash.h) against published and hand-computed vectors.
#include <gtest/gtest.h>

#include <string>

#include "skin/core/content_hash.h"

using hylios::skin::ContentHash;
using hylios::skin::fnv1a64;

TEST(ContentHash, PublishedFnv1a64Vectors) {
  // Test vectors of the FNV reference suite (Fowler, Noll, Vo; IETF draft-eastlake-fnv).
  EXPECT_EQ(fnv1a64("", 0), 0xcbf29ce484222325ULL);  // the offset basis
  EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar", 6), 0x85944171f73967e8ULL);
}

TEST(ContentHash, OneByteByHand) {
  // "a" = 0x61: basis XOR 0x61 = 0xcbf29ce484222344; the prime is 2^40 + 0x1b3, so the product
  // mod 2^64 is (x << 40) + x·0x1b3 (mod 2^64) = 0xaf63dc4c8601ec8c.
  const std::uint64_t x = 0xcbf29ce484222325ULL ^ 0x61ULL;
  EXPECT_EQ(x, 0xcbf29ce484222344ULL);
  EXPECT_EQ((x << 40) + x * 0x1b3ULL, 0xaf63dc4c8601ec8cULL);
}

TEST(ContentHash, ValuesAreLittleEndianBytes) {
  // 1 as 8 little-endian bytes 01 00 … 00; 1.0 as the bytes of 0x3ff0000000000000.
  EXPECT_EQ(ContentHash().addU64(1).value(), 0x89cd31291d2aefa4ULL);
  EXPECT_EQ(ContentHash().addDouble(1.0).value(), 0xaab1693229ba1db8ULL);
  const unsigned char one[8] = {1, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_EQ(ContentHash().addU64(1).value(), fnv1a64(one, 8));
  // A string is its length, then its bytes (so "ab" + "c" differs from "a" + "bc").
  EXPECT_NE(ContentHash().addString("ab").addString("c").value(),
            ContentHash().addString("a").addString("bc").value());
  EXPECT_EQ(ContentHash().addString("").value(), ContentHash().addU64(0).value());
}

TEST(ContentHash, ChangedValueChangesTheHash) {
  EXPECT_NE(ContentHash().addDouble(0.5).value(),
            ContentHash().addDouble(0.5000000000000001).value());
  EXPECT_NE(ContentHash().addBool(true).value(), ContentHash().addBool(false).value());
}

TEST(ContentHash, Hex64) {
  EXPECT_EQ(hylios::skin::hex64(0xcbf29ce484222325ULL), "cbf29ce484222325");
  EXPECT_EQ(hylios::skin::hex64(0x1ULL), "0000000000000001");
}
