// The run-time side of reliability through the built binary: one writer per output folder, signals
// (SIGTERM, SIGHUP) handled like Ctrl-C, no stale results of another run, staged files and staging
// folders of dead runs removed, budgets that end a run early, progress lines counted once.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>
#include <sys/stat.h>
#include <unistd.h>

#include "child_process.h"

namespace fs = std::filesystem;

namespace {

const std::string kBin = RANGESIM_BIN;
const std::string kScenes = RANGESIM_SCENE_DIR;

// A fresh folder per test: <tmp>/work is the children's working folder.
struct Workspace {
  fs::path root, work;
  Workspace() {
    char tmpl[] = "/tmp/rangesim-rel-XXXXXX";
    root = ::mkdtemp(tmpl);
    work = root / "work";
    fs::create_directory(work);
  }
  ~Workspace() { fs::remove_all(root); }
  ChildResult run(const std::string& args, double wall_s = 60) const {
    std::vector<std::string> argv = split_args(args);
    argv.insert(argv.begin(), kBin);
    return run_child(argv, work.string(), {wall_s, 0});
  }
  Background start(const std::string& args) const {
    std::vector<std::string> argv = split_args(args);
    argv.insert(argv.begin(), kBin);
    return start_child(argv, work.string());
  }
};

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) names.insert(e.path().filename().string());
  return names;
}

bool wait_for(const fs::path& p, double seconds) {
  const auto t0 = std::chrono::steady_clock::now();
  while (!fs::exists(p)) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > seconds) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// True once `p` holds a line starting with `prefix` (a journal's first finished point).
bool wait_for_line(const fs::path& p, const std::string& prefix, double seconds) {
  const auto t0 = std::chrono::steady_clock::now();
  for (;;) {
    std::ifstream in(p);
    for (std::string line; std::getline(in, line);)
      if (line.rfind(prefix, 0) == 0) return true;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > seconds) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

// A Monte Carlo sweep of a few seconds: its last point costs ~1.4 s a trial on one thread.
const std::string kSlowMc =
    "evaluate tof-spad --signal 1e5:1e8:4 --background 1e5:1e5:1 --trials 3 --threads 1 --no-plots";

TEST(Reliability, OneWriterPerFolderAndResumeNeverJoinsALiveRun) {
  Workspace w;
  const Background first = w.start(kSlowMc + " --out d");
  ASSERT_TRUE(wait_for(w.work / "d" / ".rangesim.lock", 20));
  const ChildResult second = w.run("evaluate tof-spad --no-plots --out d");
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_NE(second.err.find("--out d: another rangesim run is writing there (pid " + std::to_string(first.pid)),
            std::string::npos)
      << second.err;
  EXPECT_NE(second.err.find("rangesim evaluate tof-spad --signal 1e5:1e8:4"), std::string::npos) << second.err;
  const ChildResult resume = w.run(kSlowMc + " --out d --resume");
  EXPECT_EQ(resume.exit_code, 2) << resume.err;
  EXPECT_NE(resume.err.find("another rangesim run is writing there"), std::string::npos) << resume.err;
  // Stop it inside the Monte Carlo (its first point journaled), not in the golden grid before it:
  // only the Monte Carlo has points to keep and a --resume to offer.
  ASSERT_TRUE(wait_for_line(w.work / "d" / ".staging-sweep" / "evaluate.journal", "P ", 60));
  ::kill(first.pid, SIGTERM);
  const ChildResult stopped = wait_child(first);
  EXPECT_EQ(stopped.exit_code, 143) << stopped.err;
  EXPECT_NE(stopped.err.find("stopped by SIGTERM"), std::string::npos) << stopped.err;
  EXPECT_NE(stopped.err.find("--resume"), std::string::npos) << stopped.err;
  // The journal stays for --resume; no staging folder, no lock.
  EXPECT_EQ(names_in(w.work / "d"), std::set<std::string>{".staging-sweep"});
  const ChildResult resumed = w.run(kSlowMc + " --out d --resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const ChildResult reference = w.run(kSlowMc + " --out ref");
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  for (const auto& f : names_in(w.work / "ref")) {
    std::ifstream a(w.work / "ref" / f), b(w.work / "d" / f);
    std::stringstream sa, sb;
    sa << a.rdbuf(), sb << b.rdbuf();
    EXPECT_EQ(sa.str(), sb.str()) << f;
  }
  EXPECT_EQ(names_in(w.work / "d"), names_in(w.work / "ref"));
}

TEST(Reliability, SigtermAndSighupEndAPlainRunLeavingNothing) {
  for (const int sig : {SIGTERM, SIGHUP, SIGINT}) {
    Workspace w;
    const Background b = w.start("evaluate tof-lockin --signal 1e-11:1e-9:3000 --background 1e-14:1e-8:3000 --out d");
    ASSERT_TRUE(wait_for(w.work / "d" / ".rangesim.lock", 20));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ::kill(b.pid, sig);
    const ChildResult r = wait_child(b);
    EXPECT_EQ(r.exit_code, 128 + sig) << r.err;
    EXPECT_NE(r.err.find(sig == SIGINT    ? "interrupted (SIGINT"
                         : sig == SIGTERM ? "stopped by SIGTERM"
                                          : "SIGHUP"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("nothing written"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(w.work / "d")) << "the folder the run created stays: " << names_in(w.work / "d").size();
  }
  // In a folder of the user's, the staged files (.staging-<pid>.NAME, beside the user's) go and
  // the user's file stays.
  Workspace w;
  fs::create_directory(w.work / "d");
  std::ofstream(w.work / "d" / "mine.txt") << "mine\n";
  const Background b = w.start("evaluate tof-lockin --signal 1e-11:1e-9:3000 --background 1e-14:1e-8:3000 --out d");
  const std::string staged = ".staging-" + std::to_string(b.pid) + ".points.csv";
  ASSERT_TRUE(wait_for(w.work / "d" / staged, 20));
  ::kill(b.pid, SIGTERM);
  EXPECT_EQ(wait_child(b).exit_code, 128 + SIGTERM);
  EXPECT_EQ(names_in(w.work / "d"), std::set<std::string>{"mine.txt"});
}

TEST(Reliability, ARunReplacesItsCommandsResultsKeepsUserFilesAndRefusesAnothersWithoutForce) {
  Workspace w;
  ASSERT_EQ(w.run("evaluate tof-lockin --trials 2 --signal 1e-10:1e-9:2 --background 1e-12:1e-11:2 --no-plots --out d")
                .exit_code,
            0);
  std::ofstream(w.work / "d" / "my-notes.txt") << "mine\n";
  const ChildResult again = w.run("evaluate tof-spad --no-plots --out d");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(names_in(w.work / "d"),
            (std::set<std::string>{".rangesim-manifest", "accuracy_mm.csv", "detectable_area.csv", "my-notes.txt",
                                   "points.csv", "summary.json"}));
  const std::string scene = kScenes + "/tof-spad-plane.toml";
  const ChildResult other = w.run("simulate tof-spad --scene " + scene + " --kernel-only --no-plots --out d");
  EXPECT_EQ(other.exit_code, 2) << other.err;
  EXPECT_NE(other.err.find("holds the results of another command (4 files of `rangesim evaluate`); add --force"),
            std::string::npos)
      << other.err;
  const ChildResult forced = w.run("simulate tof-spad --scene " + scene + " --kernel-only --no-plots --force --out d");
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  const std::set<std::string> after = names_in(w.work / "d");
  EXPECT_TRUE(after.count("my-notes.txt"));
  EXPECT_TRUE(after.count("range_map.csv"));
  EXPECT_FALSE(after.count("detectable_area.csv"));
}

// A rerun moves each new file over the old one (app/file_replace.h: exchanged, the old one
// removed), leaves no staging folder, and keeps the manifest file itself when it lists the same
// files; a run writing fewer files rewrites it. A directory where a file would go is refused
// before anything moves (exit 2, naming it) and stays with what it holds.
TEST(Reliability, ARerunReplacesEachFileAndKeepsAManifestThatStillHolds) {
  Workspace w;
  const std::string run = "simulate ls-conventional --scene " + kScenes + "/plane.toml --kernel-only --out d";
  ASSERT_EQ(w.run(run).exit_code, 0);
  const fs::path d = w.work / "d";
  auto inode = [](const fs::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 ? st.st_ino : 0;
  };
  auto text = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  const ino_t manifest = inode(d / ".rangesim-manifest"), map = inode(d / "range_map.npy");
  const std::string listed = text(d / ".rangesim-manifest");
  ASSERT_NE(listed.find("file range_map.png"), std::string::npos) << listed;
  const ChildResult again = w.run(run);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(inode(d / ".rangesim-manifest"), manifest);
  EXPECT_EQ(text(d / ".rangesim-manifest"), listed);
  EXPECT_NE(inode(d / "range_map.npy"), map);  // a new file, not the old one rewritten
  EXPECT_GT(fs::file_size(d / "range_map.npy"), 1000u);
  const std::set<std::string> files = {".rangesim-manifest", "confidence_map.npy", "frames.csv",  "range_error.png",
                                       "range_map.npy",      "range_map.png",      "summary.json"};
  EXPECT_EQ(names_in(d), files);  // no staging folder left, no old file beside a new one
  const ChildResult fewer = w.run(run + " --no-plots");
  ASSERT_EQ(fewer.exit_code, 0) << fewer.err;
  // Rewritten: told by its text, not its inode (the file system may give the new manifest the
  // number of the one just removed).
  EXPECT_EQ(text(d / ".rangesim-manifest").find("png"), std::string::npos);
  EXPECT_FALSE(fs::exists(d / "range_map.png"));
  const ino_t moved = inode(d / "range_map.npy");
  fs::remove(d / "frames.csv");
  fs::create_directory(d / "frames.csv");
  std::ofstream(d / "frames.csv" / "keep.txt") << "mine\n";
  const ChildResult blocked = w.run(run + " --no-plots");
  EXPECT_EQ(blocked.exit_code, 2);
  EXPECT_NE(blocked.err.find("frames.csv: is a directory where this run writes its file frames.csv"), std::string::npos)
      << blocked.err;
  EXPECT_EQ(inode(d / "range_map.npy"), moved);  // nothing moved
  EXPECT_TRUE(fs::is_directory(d / "frames.csv"));
  EXPECT_EQ(text(d / "frames.csv" / "keep.txt"), "mine\n");
}

TEST(Reliability, StagedFilesAndFoldersOfDeadRunsAreRemoved) {
  Workspace w;
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  fs::create_directories(w.work / "d" / (".staging-" + std::to_string(dead)));
  std::ofstream(w.work / "d" / (".staging-" + std::to_string(dead)) / "points.csv") << "half\n";
  std::ofstream(w.work / "d" / (".staging-" + std::to_string(dead) + ".range_map.npy")) << "half\n";
  const std::string live = ".staging-" + std::to_string(::getpid());
  fs::create_directories(w.work / "d" / live);
  std::ofstream(w.work / "d" / (live + ".points.csv")) << "being written\n";
  ASSERT_EQ(w.run("evaluate tof-spad --no-plots --out d").exit_code, 0);
  const std::set<std::string> names = names_in(w.work / "d");
  EXPECT_FALSE(names.count(".staging-" + std::to_string(dead)));
  EXPECT_FALSE(names.count(".staging-" + std::to_string(dead) + ".range_map.npy"));
  EXPECT_TRUE(names.count(live)) << "a live process's staging folder is not touched";
  EXPECT_TRUE(names.count(live + ".points.csv")) << "a live process's staged file is not touched";
}

TEST(Reliability, AGridThatCannotFinishInItsTimeBudgetEndsOnceItsPaceIsKnown) {
  Workspace w;
  const ChildResult r =
      w.run("evaluate tof-lockin --signal 1e-11:1e-9:10000 --background 1e-14:1e-8:10000 --max-seconds 30 --out d");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_LT(r.wall_s, 15);
  EXPECT_NE(r.err.find("--max-seconds 30: the grid would take ~"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("reduce --signal/--background N"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(w.work / "d"));
}

TEST(Reliability, ARunThatOutgrowsItsMemoryBudgetEndsWithExit4) {
  Workspace w;
  const std::string run = "simulate tof-spad --scene " + kScenes +
                          "/tof-spad-plane.toml --set array.rows=1024 --set array.columns=1024 --dense "
                          "--kernel-only --frames 1 --max-memory 64M --out d";
  // The estimate refuses it up front...
  const ChildResult refused = w.run(run);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("simulate: needs about 4.28 GiB"), std::string::npos) << refused.err;
  // ... and without it the watchdog ends it as it grows.
  ::setenv("RANGESIM_SKIP_ESTIMATES", "1", 1);
  const ChildResult r = w.run(run);
  ::unsetenv("RANGESIM_SKIP_ESTIMATES");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("--max-memory 64M exceeded"), std::string::npos) << r.err;
  EXPECT_LT(r.max_rss_kib, 200 * 1024);
  EXPECT_FALSE(fs::exists(w.work / "d"));
}

TEST(Reliability, ProgressCountsRealPointsOnce) {
  Workspace w;
  const ChildResult r = w.run("evaluate tof-spad --signal 1e3:1e7:45 --background 1e3:1e7:121 --no-plots --out d");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("evaluate: 5445/5445 operating points"), std::string::npos) << r.err;
  // table evaluates every preset's grid; ls-conventional's adaptive sub-pixel average costs about
  // a minute of CPU (evaluation.subpixel_tolerance), more than the default 60 s on a loaded machine.
  const ChildResult t = w.run("table", 600);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  std::istringstream lines(t.err);
  std::set<std::string> seen;
  for (std::string line; std::getline(lines, line);) {
    const std::string counts = line.substr(0, line.find(" operating points"));
    EXPECT_TRUE(seen.insert(counts).second) << "printed twice: " << line;
  }
}

}  // namespace

// cosim all: one run per journal, its time budget and SIGTERM end it between targets with the
// journal kept and the exit code of the cause (4, 143), and --resume completes it.
TEST(Reliability, CosimAllLocksItsJournalAndStopsBetweenTargets) {
  Workspace w;
  const Background first = w.start("cosim all --cycles 400000 --journal j/all.journal");
  ASSERT_TRUE(wait_for(w.work / "j" / ".rangesim.lock", 20));
  const ChildResult second = w.run("cosim all --cycles 400000 --journal j/all.journal --resume");
  EXPECT_EQ(second.exit_code, 2) << second.err;
  EXPECT_NE(second.err.find("--journal " + (w.work / "j").string() + ": another rangesim run is writing there (pid " +
                            std::to_string(first.pid)),
            std::string::npos)
      << second.err;
  ASSERT_TRUE(wait_for(w.work / "j" / "all.journal", 20));
  ::kill(first.pid, SIGTERM);
  const ChildResult stopped = wait_child(first);
  EXPECT_EQ(stopped.exit_code, 143) << stopped.err;
  EXPECT_NE(stopped.err.find("stopped by SIGTERM"), std::string::npos) << stopped.err;
  EXPECT_NE(stopped.err.find("--resume"), std::string::npos) << stopped.err;
  EXPECT_EQ(names_in(w.work / "j"), std::set<std::string>{"all.journal"});

  const ChildResult budget = w.run("cosim all --cycles 400000 --journal k/all.journal --max-seconds 2");
  EXPECT_EQ(budget.exit_code, 4) << budget.err;
  EXPECT_NE(budget.err.find("cosim: --max-seconds 2 exceeded"), std::string::npos) << budget.err;
  EXPECT_EQ(names_in(w.work / "k"), std::set<std::string>{"all.journal"});
}

TEST(Reliability, CosimOfOneTargetHonoursItsTimeBudget) {
  Workspace w;
  const ChildResult r = w.run("cosim address_search --cycles 100000000 --max-seconds 1");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("--max-seconds"), std::string::npos) << r.err;
  EXPECT_LT(r.wall_s, 20);
}

// A folder written before output manifests existed: refused without --force (its files cannot be
// told from the user's), written into with it.
TEST(Reliability, AFolderOfAnEarlierRunWithoutManifestNeedsForce) {
  Workspace w;
  fs::create_directory(w.work / "old");
  std::ofstream(w.work / "old" / "summary.json") << "{}\n";
  std::ofstream(w.work / "old" / "mc_points.csv") << "old\n";
  const ChildResult r = w.run("evaluate tof-spad --signal 1e3:1e5:3 --background 1e3:1e5:3 --no-plots --out old");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--out old: holds an earlier rangesim run without a record of its files"), std::string::npos)
      << r.err;
  const ChildResult forced =
      w.run("evaluate tof-spad --signal 1e3:1e5:3 --background 1e3:1e5:3 --no-plots --out old --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_TRUE(fs::exists(w.work / "old" / ".rangesim-manifest"));
  EXPECT_TRUE(fs::exists(w.work / "old" / "mc_points.csv"));  // not known to be rangesim's: it stays
}
