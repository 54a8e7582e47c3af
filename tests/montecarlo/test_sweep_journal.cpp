// The sweep journal: records survive reopening, a torn last record is dropped, a journal of other
// options is refused, an existing journal is never silently overwritten.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/sweep_journal.h"
#include "core/user_error.h"
#include "run_command.h"

namespace rangesim::app {
namespace {

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(SweepJournal, RecordsSurviveReopening) {
  const std::string path = make_temp_dir() + "/staging/j.journal";
  {
    SweepJournal j(path, "preset a\noption b", false);
    EXPECT_TRUE(j.done().empty());
    j.append(3, "0x1.8p+1 nan");
    j.append(0, "first");
  }
  SweepJournal j(path, "preset a\noption b", true);
  ASSERT_EQ(j.done().size(), 2u);
  EXPECT_EQ(j.done().at(3), "0x1.8p+1 nan");
  EXPECT_EQ(j.done().at(0), "first");
  j.append(7, "more");
  SweepJournal k(path, "preset a\noption b", true);
  EXPECT_EQ(k.done().size(), 3u);
}

TEST(SweepJournal, TornLastRecordIsDroppedAndOverwritten) {
  const std::string path = make_temp_dir() + "/j.journal";
  {
    SweepJournal j(path, "fp", false);
    j.append(1, "one");
    j.append(2, "two");
  }
  // A kill in the middle of a record: cut the file inside the last line; then a corrupted line.
  std::string text = slurp(path);
  std::filesystem::resize_file(path, text.size() - 5);
  {
    SweepJournal j(path, "fp", true);
    EXPECT_EQ(j.done().size(), 1u);
    j.append(2, "two again");
  }
  SweepJournal j(path, "fp", true);
  ASSERT_EQ(j.done().size(), 2u);
  EXPECT_EQ(j.done().at(2), "two again");
  // A flipped byte in a record fails its hash: that record and everything after it are dropped.
  text = slurp(path);
  text[text.find("one")] = 'x';
  std::ofstream(path, std::ios::binary) << text;
  SweepJournal bad(path, "fp", true);
  EXPECT_TRUE(bad.done().empty());
}

TEST(SweepJournal, OtherOptionsAreRefused) {
  const std::string path = make_temp_dir() + "/j.journal";
  { SweepJournal j(path, "sensor = tof-spad\ntrials = 100\n", false); }
  try {
    SweepJournal j(path, "sensor = tof-spad\ntrials = 200\n", true);
    FAIL() << "accepted a journal of other options";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("journal has `trials = 100`, this run has `trials = 200`"), std::string::npos)
        << e.what();
  }
}

TEST(SweepJournal, ExistingJournalNeedsResume) {
  const std::string path = make_temp_dir() + "/j.journal";
  { SweepJournal j(path, "fp", false); }
  EXPECT_THROW(SweepJournal(path, "fp", false), UserError);
  SweepJournal j(path, "fp", true);
  j.remove();
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace rangesim::app
