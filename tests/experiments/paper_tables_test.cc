// The paper's figures as data (experiments/paper_tables.h): the shipped file loads and holds
// Table 1's cells as printed (Ros et al. 2009, sec. 5.2.1); a claim's direction comes from the
// cells; a bad file is one line naming the file and the field.
#include "experiments/paper_tables.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

PaperTables Shipped() {
  return LoadPaperTables("ros2009_tables", testing::ModelsDir());
}

double Cell(const PaperTables& p, int table, int scenario, const std::string& team,
            const std::string& measure, const std::string& robot = "") {
  const PaperTable* t = p.Table(table);
  EXPECT_NE(t, nullptr);
  const PaperRow* row = t->Row(scenario, team);
  EXPECT_NE(row, nullptr);
  const auto c = t->ValueColumn(measure, robot);
  EXPECT_TRUE(c.has_value());
  return row->values[*c];
}

TEST(PaperTablesTest, ShippedFileHoldsTable1AsPrinted) {
  const PaperTables p = Shipped();
  ASSERT_EQ(p.tables.size(), 5u);
  EXPECT_EQ(Cell(p, 1, 4, "cbr", "goal"), 36);
  EXPECT_EQ(Cell(p, 1, 4, "cbr", "block"), 45);
  EXPECT_EQ(Cell(p, 1, 4, "cbr", "to_goal"), 44);
  EXPECT_EQ(Cell(p, 1, 3, "reactive", "touches", "D"), 2.20);
  EXPECT_EQ(p.Table(1)->rows.size(), 8u);
  EXPECT_EQ(p.Table(2)->rows.size(), 4u);
  EXPECT_EQ(p.Table(5)->config, "2d");
  EXPECT_EQ(Cell(p, 5, 4, "reactive", "time_without_timeouts_s"), 24.87);
}

TEST(PaperTablesTest, ClaimsSumTheirColumnsAndTheDirectionComesFromTheCells) {
  const PaperTables p = Shipped();
  ASSERT_EQ(p.claims.size(), 4u);
  const PaperClaim& possessions = p.claims[2];
  EXPECT_NEAR(*PaperClaimValue(p, possessions, "2d", 1, "cbr"), 1.14 + 0.51, 1e-12);
  const PaperClaim& time = p.claims[3];
  // DG: CBR's trials are longer in scenarios 1-3 and shorter in 4 (Table 1).
  EXPECT_GT(*PaperClaimValue(p, time, "dg", 3, "cbr"), *PaperClaimValue(p, time, "dg", 3, "reactive"));
  EXPECT_LT(*PaperClaimValue(p, time, "dg", 4, "cbr"), *PaperClaimValue(p, time, "dg", 4, "reactive"));
  EXPECT_FALSE(PaperClaimValue(p, time, "3d", 1, "cbr").has_value());
}

std::string ShippedText() {
  return testing::ReadText(testing::ModelsDir() / "experiments" / "ros2009_tables.json");
}

std::string ErrorOf(const std::string& name, const std::string& text) {
  const auto file = testing::WriteTempFile(name, text);
  try {
    LoadPaperTables(file.string(), testing::ModelsDir());
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind(file.string() + ": ", 0), 0u) << what;
    return what;
  }
  ADD_FAILURE() << "no error";
  return "";
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(PaperTablesTest, BadFilesAreOneLineNamingFileAndField) {
  const std::string good = ShippedText();
  EXPECT_NE(ErrorOf("share.json", Replace(good, "[25, 9, 38, 28, 34, 1.34", "[125, 9, 38, 28, 34, 1.34"))
                .find("tables[0].rows[0].values[0]: must be in [0, 100]"),
            std::string::npos);
  EXPECT_NE(ErrorOf("count.json", Replace(good, "[3.3, 16.0, 17, 83]", "[3.3, 16.0, 17]"))
                .find("tables[1].rows[0].values: has 3 numbers, the table 4 columns"),
            std::string::npos);
  EXPECT_NE(ErrorOf("key.json", Replace(good, "\"caption\":", "\"colour\": \"red\", \"caption\":"))
                .find("colour"),
            std::string::npos);
  EXPECT_NE(ErrorOf("stat.json", Replace(good, "{\"measure\": \"goal\", \"stat\": \"pct\"}",
                                         "{\"measure\": \"goal\", \"stat\": \"sd\"}"))
                .find("tables[0].columns[0].stat: 'goal' has no sd"),
            std::string::npos);
  EXPECT_NE(ErrorOf("term.json", Replace(good, "{\"table\": 4, \"measure\": \"out\"}",
                                         "{\"table\": 5, \"measure\": \"out\"}"))
                .find("claims[1].terms.2d[0].measure: table 5 has no column out"),
            std::string::npos);
}

}  // namespace
}  // namespace foresight
