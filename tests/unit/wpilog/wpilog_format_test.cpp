// The writer produces the byte layouts of the specification's examples, and the reader reads
// back whatever the writer wrote (every type, every field width) and rejects malformed files.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "cyber/wpilog/pose3d.hpp"
#include "cyber/wpilog/wpilog_reader.hpp"
#include "cyber/wpilog/wpilog_writer.hpp"

namespace cyber::wpilog {
namespace {

std::vector<uint8_t> tail(const std::vector<uint8_t>& bytes, size_t from) {
  return {bytes.begin() + static_cast<long>(from), bytes.end()};
}

Log parsed(const Writer& w) {
  auto r = parse(w.bytes());
  EXPECT_TRUE(r.ok()) << r.error().message;
  return r.ok() ? std::move(r).value() : Log{};
}

TEST(WpilogFormat, HeaderIsTheSpecificationsEmptyHeader) {
  const Writer w;
  EXPECT_EQ(w.bytes(), (std::vector<uint8_t>{0x57, 0x50, 0x49, 0x4c, 0x4f, 0x47, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00}));
}

TEST(WpilogFormat, StartAndInt64RecordsAreTheSpecificationsExamples) {
  Writer w;
  const uint32_t id = w.start("test", "int64", "", 1000000);
  ASSERT_EQ(id, 1u);
  const std::vector<uint8_t> start{0x20, 0x00, 0x1a, 0x40, 0x42, 0x0f, 0x00, 0x01, 0x00, 0x00, 0x00,
                                   0x04, 0x00, 0x00, 0x00, 0x74, 0x65, 0x73, 0x74, 0x05, 0x00, 0x00,
                                   0x00, 0x69, 0x6e, 0x74, 0x36, 0x34, 0x00, 0x00, 0x00, 0x00};
  EXPECT_EQ(tail(w.bytes(), 12), start);
  const size_t before = w.bytes().size();
  w.appendInt64(id, 1000000, 3);
  EXPECT_EQ(tail(w.bytes(), before),
            (std::vector<uint8_t>{0x20, 0x01, 0x08, 0x40, 0x42, 0x0f, 0x03, 0, 0, 0, 0, 0, 0, 0}));
  const size_t before_finish = w.bytes().size();
  w.finish(id, 1000000);
  EXPECT_EQ(tail(w.bytes(), before_finish),
            (std::vector<uint8_t>{0x20, 0x00, 0x05, 0x40, 0x42, 0x0f, 0x01, 0x01, 0, 0, 0}));
}

TEST(WpilogFormat, SetMetadataIsTheSpecificationsExample) {
  Writer w;
  const uint32_t id = w.start("test", "int64", "", 1000000);
  const size_t before = w.bytes().size();
  w.setMetadata(id, R"({"source":"NT"})", 1000000);
  EXPECT_EQ(
      tail(w.bytes(), before),
      (std::vector<uint8_t>{0x20, 0x00, 0x18, 0x40, 0x42, 0x0f, 0x02, 0x01, 0x00, 0x00, 0x00, 0x0f, 0x00, 0x00, 0x00,
                            0x7b, 0x22, 0x73, 0x6f, 0x75, 0x72, 0x63, 0x65, 0x22, 0x3a, 0x22, 0x4e, 0x54, 0x22, 0x7d}));
  const Log log = parsed(w);
  ASSERT_EQ(log.entries.size(), 1u);
  EXPECT_EQ(log.entries[0].metadata, R"({"source":"NT"})");
}

TEST(WpilogFormat, EveryStandardTypeRoundTrips) {
  Writer w("extra header");
  const uint32_t b = w.start("/b", "boolean", "{}", 1);
  const uint32_t i = w.start("/i", "int64", "", 2);
  const uint32_t f = w.start("/f", "float", "", 3);
  const uint32_t d = w.start("/d", "double", "", 4);
  const uint32_t s = w.start("/s", "string", "", 5);
  const uint32_t ba = w.start("/ba", "boolean[]", "", 6);
  const uint32_t ia = w.start("/ia", "int64[]", "", 7);
  const uint32_t da = w.start("/da", "double[]", "", 8);
  const uint32_t sa = w.start("/sa", "string[]", "", 9);
  w.appendBoolean(b, 10, true);
  w.appendInt64(i, 11, std::numeric_limits<int64_t>::min());
  w.appendFloat(f, 12, -1.5f);
  w.appendDouble(d, 13, 6.02214076e23);
  w.appendString(s, 14, "héllo");
  const bool bools[] = {true, false, true};
  w.appendBooleanArray(ba, 15, bools);
  const int64_t ints[] = {-1, 0, 1LL << 40};
  w.appendInt64Array(ia, 16, ints);
  const double doubles[] = {0.1, -0.0, 1e300};
  w.appendDoubleArray(da, 17, doubles);
  const std::string strings[] = {"", "a", "two words"};
  w.appendStringArray(sa, 18, strings);

  const Log log = parsed(w);
  EXPECT_EQ(log.version, 0x0100);
  EXPECT_EQ(log.extra_header, "extra header");
  ASSERT_EQ(log.entries.size(), 9u);
  ASSERT_EQ(log.records.size(), 9u);
  EXPECT_EQ(log.entries[0].name, "/b");
  EXPECT_EQ(log.entries[0].metadata, "{}");
  EXPECT_EQ(log.entries[8].type, "string[]");
  EXPECT_EQ(log.records[0].timestamp_us, 10u);
  EXPECT_EQ(asBoolean(log.payload(log.records[0])), true);
  EXPECT_EQ(asInt64(log.payload(log.records[1])), std::numeric_limits<int64_t>::min());
  EXPECT_EQ(asFloat(log.payload(log.records[2])), -1.5f);
  EXPECT_EQ(asDouble(log.payload(log.records[3])), 6.02214076e23);
  EXPECT_EQ(asString(log.payload(log.records[4])), "héllo");
  EXPECT_EQ(asBooleanArray(log.payload(log.records[5])), (std::vector<bool>{true, false, true}));
  EXPECT_EQ(asInt64Array(log.payload(log.records[6])), (std::vector<int64_t>{-1, 0, 1LL << 40}));
  EXPECT_EQ(asDoubleArray(log.payload(log.records[7])), (std::vector<double>{0.1, -0.0, 1e300}));
  EXPECT_EQ(asStringArray(log.payload(log.records[8])), (std::vector<std::string>{"", "a", "two words"}));
  for (const Record& r : log.records) EXPECT_TRUE(decodesAs(log.entries[r.entry].type, log.payload(r)));
}

// Random entry ids, payload sizes and timestamps cover every width of the three header fields.
TEST(WpilogFormat, RandomRecordsOfEveryFieldWidthRoundTrip) {
  std::mt19937_64 rng(15);
  Writer w;
  std::vector<uint32_t> ids;
  for (int k = 0; k < 300; ++k) ids.push_back(w.start("/e" + std::to_string(k), "raw", "", 0));
  struct Expected {
    uint32_t id;
    uint64_t t;
    std::vector<uint8_t> payload;
  };
  std::vector<Expected> expected;
  const size_t sizes[] = {0, 1, 255, 256, 65535, 65536, 70000};
  for (int k = 0; k < 200; ++k) {
    const int width = static_cast<int>(rng() % 8) + 1;
    const uint64_t t = width == 8 ? rng() : rng() % (1ULL << (8 * width));
    std::vector<uint8_t> payload(sizes[rng() % std::size(sizes)]);
    for (auto& byte : payload) byte = static_cast<uint8_t>(rng());
    const uint32_t id = ids[rng() % ids.size()];
    w.appendRaw(id, t, payload);
    expected.push_back({id, t, payload});
  }
  const Log log = parsed(w);
  ASSERT_EQ(log.records.size(), expected.size());
  for (size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(log.entries[log.records[k].entry].id, expected[k].id);
    EXPECT_EQ(log.records[k].timestamp_us, expected[k].t);
    const auto p = log.payload(log.records[k]);
    EXPECT_TRUE(std::equal(p.begin(), p.end(), expected[k].payload.begin(), expected[k].payload.end()));
  }
}

TEST(WpilogFormat, AnIdReusedAfterFinishIsANewEntry) {
  Writer w;
  const uint32_t id = w.start("/a", "double", "", 0);
  w.appendDouble(id, 1, 1.0);
  w.finish(id, 2);
  // The writer never reuses ids; a hand-made Start for id 1 again is what another writer may do.
  std::vector<uint8_t> bytes = w.bytes();
  const std::vector<uint8_t> restart{0x00, 0x00, 0x19, 0x03, 0x00, 0x01, 0x00, 0x00, 0x00, 0x02,
                                     0x00, 0x00, 0x00, '/',  'b',  0x06, 0x00, 0x00, 0x00, 's',
                                     't',  'r',  'i',  'n',  'g',  0x00, 0x00, 0x00, 0x00};
  bytes.insert(bytes.end(), restart.begin(), restart.end());
  const std::vector<uint8_t> value{0x00, 0x01, 0x02, 0x04, 'h', 'i'};
  bytes.insert(bytes.end(), value.begin(), value.end());
  const auto r = parse(bytes);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->entries.size(), 2u);
  EXPECT_EQ(r->entries[r->records.back().entry].name, "/b");
  EXPECT_EQ(asString(r->payload(r->records.back())), "hi");
}

TEST(WpilogFormat, Pose3dArraysRoundTripWithTheirSchemas) {
  Writer w;
  addPose3dSchemas(w, 0);
  const uint32_t id = w.start("/poses", "struct:Pose3d[]", "", 0);
  const Pose3d poses[] = {{1, 2, 3, 1, 0, 0, 0}, {-1, 0, 0.5, 0.5, 0.5, -0.5, 0.5}};
  w.appendRaw(id, 5, packPose3dArray(poses));
  const Log log = parsed(w);
  const auto schema = log.find("/.schema/struct:Pose3d");
  ASSERT_TRUE(schema);
  EXPECT_EQ(log.entries[*schema].type, "structschema");
  EXPECT_EQ(asString(log.payload(*log.recordsOf(*schema).front())), "Translation3d translation;Rotation3d rotation");
  for (const char* name :
       {"/.schema/struct:Translation3d", "/.schema/struct:Rotation3d", "/.schema/struct:Quaternion"}) {
    EXPECT_TRUE(log.find(name)) << name;
  }
  std::vector<Pose3d> back;
  ASSERT_TRUE(unpackPose3dArray(log.payload(log.records.back()), &back));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(log.payload(log.records.back()).size(), 2 * kPose3dBytes);
  EXPECT_EQ(back[1].x, -1);
  EXPECT_EQ(back[1].qy, -0.5);
}

WpilogStatus errorOf(std::vector<uint8_t> bytes) {
  const auto r = parse(std::move(bytes));
  EXPECT_FALSE(r.ok());
  return r.status();
}

TEST(WpilogFormat, MalformedFilesAreTypedErrors) {
  Writer w;
  const uint32_t id = w.start("/x", "double", "", 0);
  w.appendDouble(id, 1, 2.0);
  const std::vector<uint8_t> good = w.bytes();

  EXPECT_EQ(errorOf({}), WpilogStatus::kTruncated);
  std::vector<uint8_t> magic = good;
  magic[0] = 'X';
  EXPECT_EQ(errorOf(magic), WpilogStatus::kBadMagic);
  std::vector<uint8_t> version = good;
  version[7] = 2;
  EXPECT_EQ(errorOf(version), WpilogStatus::kUnsupportedVersion);
  std::vector<uint8_t> extra = good;
  extra[8] = 0xff;  // extra header longer than the file
  EXPECT_EQ(errorOf(extra), WpilogStatus::kTruncated);
  // Every cut inside a record is a truncation, never a crash or a silently short log.
  for (size_t cut = 13; cut < good.size(); ++cut) {
    if (cut == 12 + 29) continue;  // the boundary between the Start record and the data record
    EXPECT_EQ(errorOf({good.begin(), good.begin() + static_cast<long>(cut)}), WpilogStatus::kTruncated) << cut;
  }
  std::vector<uint8_t> unknown = good;
  unknown[unknown.size() - 11] = 7;  // the data record's entry id
  EXPECT_EQ(errorOf(unknown), WpilogStatus::kUnknownEntry);
  std::vector<uint8_t> control = good;
  control[12 + 4] = 9;  // control type of the Start record
  EXPECT_EQ(errorOf(control), WpilogStatus::kBadControlRecord);
  std::vector<uint8_t> name = good;
  name[12 + 9] = 0x7f;  // name length past the record
  EXPECT_EQ(errorOf(name), WpilogStatus::kBadControlRecord);
  Writer finish;
  finish.finish(5, 0);
  EXPECT_EQ(errorOf(finish.bytes()), WpilogStatus::kUnknownEntry);
  EXPECT_EQ(readFile("/nonexistent/x.wpilog").status(), WpilogStatus::kCannotOpen);
}

TEST(WpilogFormat, DecodersRejectPayloadsOfTheWrongSize) {
  const std::vector<uint8_t> seven(7, 0);
  EXPECT_FALSE(asDouble(seven));
  EXPECT_FALSE(asInt64(seven));
  EXPECT_FALSE(asDoubleArray(seven));
  EXPECT_FALSE(asBoolean(seven));
  EXPECT_FALSE(asFloat(seven));
  EXPECT_FALSE(decodesAs("double", seven));
  EXPECT_TRUE(decodesAs("string", seven));
  const std::vector<uint8_t> count_too_big{2, 0, 0, 0, 1, 0, 0, 0, 'a'};
  EXPECT_FALSE(asStringArray(count_too_big));
  std::vector<Pose3d> poses;
  EXPECT_FALSE(unpackPose3dArray(std::vector<uint8_t>(8, 0), &poses));
}

TEST(WpilogFormat, WriteFileNamesAPathItCannotWrite) {
  const auto written = Writer().writeFile("/nonexistent/x.wpilog");
  ASSERT_EQ(written.status(), WpilogStatus::kCannotWrite);
  EXPECT_EQ(written.error().message, "/nonexistent/x.wpilog: cannot write");
}

}  // namespace
}  // namespace cyber::wpilog
