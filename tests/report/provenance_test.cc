// The provenance every report carries: inputs in order, replaced in place, and its JSON and HTML
// pieces.
#include "report/provenance.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

RunProvenance Example() {
  RunProvenance p;
  p.version = "1.2.3";
  p.seed = 7;
  p.run_time_s = 12.34;
  p.inputs = {{"file", "experiments/a.json"}, {"situation", "scene"}};
  return p;
}

TEST(ProvenanceTest, SetInputReplacesInPlaceOrAppends) {
  RunProvenance p = Example();
  p.SetInput("file", "experiments/b.json");
  p.SetInput("kicks", "kicks/nao.json");
  ASSERT_EQ(p.inputs.size(), 3u);
  EXPECT_EQ(p.inputs[0].key, "file");
  EXPECT_EQ(p.Input("file"), "experiments/b.json");
  EXPECT_EQ(p.inputs[2].key, "kicks");
  EXPECT_EQ(p.Input("missing"), "");
}

TEST(ProvenanceTest, InputsKeepTheirOrderInTheJson) {
  nlohmann::ordered_json j{{"experiment", "x"}};
  AddInputsJson(j, Example());
  EXPECT_EQ(j.dump(), R"({"experiment":"x","file":"experiments/a.json","situation":"scene"})");
  EXPECT_EQ(InputsJson(RunProvenance{}).dump(), "{}");
}

TEST(ProvenanceTest, HtmlRowsEndWithVersionAndRunTime) {
  const auto rows = ProvenanceRows(Example());
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], (std::pair<std::string, std::string>{"version", "1.2.3"}));
  EXPECT_EQ(rows[1], (std::pair<std::string, std::string>{"run time", "12.3 s"}));
}

TEST(ProvenanceTest, ContentHashIsFnv1a64OfTheBytes) {
  const std::string id = std::to_string(::getpid());
  // FNV-1a 64 of "" and of "a" (the published test vectors).
  EXPECT_EQ(ContentHash(testing::WriteTempFile("hash_empty_" + id, "")),
            "fnv1a64:cbf29ce484222325");
  EXPECT_EQ(ContentHash(testing::WriteTempFile("hash_a_" + id, "a")), "fnv1a64:af63dc4c8601ec8c");
  // One changed byte changes the hash.
  EXPECT_NE(ContentHash(testing::WriteTempFile("hash_b_" + id, "{\"x\": 1}")),
            ContentHash(testing::WriteTempFile("hash_c_" + id, "{\"x\": 2}")));
  EXPECT_THROW(ContentHash(testing::FreshTempDir("hash_" + id) / "absent"), InputError);
  EXPECT_EQ(ContentHash(""), "");  // data from memory has no file to hash
}

// A FIFO in a data file's place is refused at once (the hash read it with std::ifstream, whose
// open waits for a writer that never comes), like every reader's input.
TEST(ProvenanceTest, ContentHashRefusesAFifoWithoutWaiting) {
  const std::filesystem::path fifo =
      testing::FreshTempDir("hash_fifo_" + std::to_string(::getpid())) / "kicks.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    ContentHash(fifo);
    ADD_FAILURE() << "a FIFO was hashed";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              fifo.string() + ": is not a regular file (a device or a pipe?)");
  }
}

TEST(ProvenanceTest, JoinDistinctKeepsFirstAppearances) {
  EXPECT_EQ(JoinDistinct({"kicks/nao.json", "kicks/aibo.json", "kicks/nao.json"}),
            "kicks/nao.json, kicks/aibo.json");
  EXPECT_EQ(JoinDistinct({}), "");
}

}  // namespace
}  // namespace foresight
