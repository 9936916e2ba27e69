#include "app/bench/bench.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <set>
#include <system_error>
#include <thread>

#include <CLI/CLI.hpp>

#include "app/bench/experiments.h"
#include "app/bench/runner.h"
#include "app/interrupt.h"
#include "app/output_files.h"
#include "app/settings.h"
#include "scenes/scene_file.h"

namespace app {
namespace fs = std::filesystem;

namespace {

struct BenchOptions {
  bool quick = false;
  std::string out;
  std::vector<std::string> only;    // empty: every experiment
  std::vector<std::string> scenes;  // empty: every scene model
  int threads = 0;
};

std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> names;
  std::string current;
  for (char ch : text + ",") {
    if (ch != ',') {
      current += ch;
      continue;
    }
    names.push_back(current);
    current.clear();
  }
  return names;
}

// The comma-separated names of `flag`, each one of `valid` (UsageError otherwise).
std::vector<std::string> checked_names(const char* flag, const std::string& text,
                                       const std::vector<std::string>& valid) {
  std::string valid_text;
  for (const std::string& v : valid) valid_text += (valid_text.empty() ? "" : "|") + v;
  std::vector<std::string> names = split_names(text);
  for (const std::string& name : names) {
    if (std::find(valid.begin(), valid.end(), name) == valid.end()) {
      throw UsageError(std::string(flag) + ": must be one or more of " + valid_text +
                       " (comma-separated), got '" + text + "'");
    }
  }
  return names;
}

// Every check happens here, before the output folder is created.
BenchOptions parse_options(const BenchFlags& flags) {
  BenchOptions o;
  if (flags.suite != "thesis")
    throw UsageError("--suite: must be thesis, got '" + flags.suite + "'");
  if (flags.out.empty()) throw UsageError("--out: needs a folder for the results, got ''");
  // The nearest part of the path that exists (a dangling symlink counts: it is a name) must be a
  // folder, or every folder below it would fail to be made after the checks.
  std::error_code ec;
  fs::path existing = fs::absolute(fs::path(flags.out), ec);
  while (!existing.empty() && existing != existing.parent_path() &&
         !fs::exists(fs::symlink_status(existing, ec))) {
    existing = existing.parent_path();
  }
  const std::string got = ", got '" + flags.out + "'";
  const fs::file_status status = fs::status(existing, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) {
    // A symlink loop, or a component that is not a folder.
    throw UsageError("--out: cannot be a folder (" + ec.message() + ")" + got);
  }
  if (!fs::exists(status)) {
    throw UsageError("--out: '" + existing.string() + "' is a symlink to nothing" + got);
  }
  if (!fs::is_directory(status)) {
    throw UsageError(existing == fs::absolute(fs::path(flags.out), ec)
                         ? "--out: is not a folder" + got
                         : "--out: '" + existing.string() + "' is not a folder" + got);
  }
  if (::access(existing.c_str(), W_OK) != 0) {
    throw UsageError("--out: folder is not writable" + got);
  }
  o.out = flags.out;
  o.quick = flags.quick;
  if (flags.only_given) o.only = checked_names("--only", flags.only, bench_experiment_names());
  if (flags.scenes_given) {
    o.scenes = checked_names("--scenes", flags.scenes,
                             bench::suite_scene_names(bench::thesis_suite(o.quick)));
  }
  if (flags.threads_given) {
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(flags.threads.c_str(), &end, 10);
    // The settings' integer grammar (no sign, space or hex), as render's --threads takes it.
    if (!is_decimal_integer(flags.threads) || errno != 0 || *end != '\0' || v < 0 || v > 1024) {
      throw UsageError("--threads: must be an integer in [0, 1024], got '" + flags.threads + "'");
    }
    o.threads = static_cast<int>(v);
  }
  return o;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const std::size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown CPU";
}

std::string utc_date() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", &tm);
  return buffer;
}

std::string command_text(const BenchOptions& o) {
  std::string c = "levrt bench --suite thesis --out " + o.out;
  if (o.quick) c += " --quick";
  if (!o.only.empty()) {
    c += " --only ";
    for (std::size_t i = 0; i < o.only.size(); ++i) c += (i ? "," : "") + o.only[i];
  }
  if (!o.scenes.empty()) {
    c += " --scenes ";
    for (std::size_t i = 0; i < o.scenes.size(); ++i) c += (i ? "," : "") + o.scenes[i];
  }
  if (o.threads > 0) c += " --threads " + std::to_string(o.threads);
  return c;
}

bool selected(const BenchOptions& o, const std::string& name) {
  return o.only.empty() || std::find(o.only.begin(), o.only.end(), name) != o.only.end();
}

}  // namespace

std::vector<std::string> bench_experiment_names() {
  std::vector<std::string> names;
  for (const bench::ExperimentInfo& e : bench::experiments()) names.emplace_back(e.name);
  return names;
}

void add_bench_flags(CLI::App& command, BenchFlags& flags) {
  command.add_option("--suite", flags.suite, "experiment suite (thesis)");
  command.add_option("--out", flags.out,
                     "folder for results.md, the CSVs and the plots (created if missing)");
  command.add_flag("--quick", flags.quick,
                   "small sizes, for CI: checks the harness, not the figures");
  std::string names;
  for (const std::string& n : bench_experiment_names()) names += (names.empty() ? "" : ", ") + n;
  command
      .add_option("--only", flags.only,
                  "run only these experiments (comma-separated: " + names + ")")
      ->each([&flags](const std::string&) { flags.only_given = true; });
  std::string scenes;
  for (const std::string& n : bench::suite_scene_names(bench::thesis_suite(false)))
    scenes += (scenes.empty() ? "" : ", ") + n;
  command
      .add_option(
          "--scenes", flags.scenes,
          "render only these scene models in every experiment (comma-separated: " + scenes + ")")
      ->each([&flags](const std::string&) { flags.scenes_given = true; });
  command.add_option("--threads", flags.threads, "worker threads (0 = all cores)")
      ->each([&flags](const std::string&) { flags.threads_given = true; });
}

namespace {

// Refuses, before any render, a file of the suite that the output folder cannot take (a folder,
// a socket or a block device of that name, a symlink loop): found when the suite was done, it
// lost every result.
void check_planned_outputs(const bench::BenchRun& run, const std::string& destination) {
  std::set<std::string> names(run.planned_outputs().begin(), run.planned_outputs().end());
  names.insert("results.md");
  std::vector<OutputPath> outputs;
  for (const std::string& name : names) {
    outputs.push_back({"--out", (fs::path(destination) / name).string(),
                       fs::path(name).extension().string(), "the suite's file"});
  }
  check_output_paths(outputs);
}

// Refuses, once planned, --scenes that leave an experiment of --only (or, without --only, the
// whole suite) with nothing to render: it ran to exit 0 with empty tables.
void check_scenes_are_rendered(const BenchOptions& options, const bench::BenchRun& run) {
  if (options.scenes.empty()) return;
  std::string scenes;
  for (const std::string& s : options.scenes) scenes += (scenes.empty() ? "" : ",") + s;
  std::string idle;
  bool any = false;
  for (const bench::ExperimentInfo& e : bench::experiments()) {
    if (!selected(options, e.name)) continue;
    if (run.planned_jobs(e.name) > 0) {
      any = true;
    } else {
      idle += (idle.empty() ? "" : ", ") + std::string(e.name);
    }
  }
  if (!options.only.empty() && !idle.empty()) {
    throw UsageError("--scenes: none of these scenes is rendered by " + idle + ", got '" + scenes +
                     "'");
  }
  if (!any)
    throw UsageError("--scenes: none of these scenes is rendered by any experiment, got '" +
                     scenes + "'");
}

// The whole suite, its files written into out_dir (the staging folder) and then published into
// destination. Returns how many experiments ran.
std::size_t run_suite(const BenchOptions& options, const std::string& out_dir,
                      const std::string& destination) {
#ifndef NDEBUG
  std::fprintf(stderr,
               "levrt bench: warning: not a Release build, the timings are not representative\n");
#endif
  bench::SuiteConfig config = bench::thesis_suite(options.quick);
  if (!options.scenes.empty()) bench::restrict_to_scenes(config, options.scenes);
  bench::BenchRun run(config, options.threads);

  // Planning pass: every selected experiment walks its measurements without rendering, so the
  // progress estimate knows the whole suite.
  for (const bench::ExperimentInfo& e : bench::experiments()) {
    if (!selected(options, e.name)) continue;
    run.begin_experiment(e.name);
    e.run(run, out_dir);
  }
  check_scenes_are_rendered(options, run);
  check_planned_outputs(run, destination);
  run.start_running();

  std::vector<bench::Section> sections;
  std::vector<std::string> names;
  for (const bench::ExperimentInfo& e : bench::experiments()) {
    if (!selected(options, e.name)) continue;
    run.begin_experiment(e.name);
    sections.push_back(e.run(run, out_dir));
    names.emplace_back(e.name);
  }

  const bench::SuiteConfig& c = run.config();
  const unsigned hardware = std::thread::hardware_concurrency();
  std::string md = "# levrt bench: the thesis' experiments\n\n";
  md += "Produced by `" + command_text(options) + "` on " + utc_date() + ": " + cpu_model() + ", " +
        std::to_string(hardware) + " hardware threads, " +
        (options.threads > 0 ? std::to_string(options.threads)
                             : "all (" + std::to_string(hardware) + ")") +
        " worker threads, " +
#ifdef NDEBUG
        "Release build.\n\n";
#else
        "**not a Release build: timings are not representative**.\n\n";
#endif
  if (c.quick)
    md +=
        "**Quick run** (`--quick`): small images and light counts. It checks the harness; its "
        "figures are not the experiments'.\n\n";
  md += "Every figure is from one " + std::to_string(c.width) + "x" + std::to_string(c.height) +
        " frame, one sample per pixel at the pixel centres, Whitted recursion to depth 5. The "
        "scene, its light hierarchy and its Embree BVH are built first and not timed; fitting the "
        "extent volumes and setting up the selector are. Times are the median of at least " +
        std::to_string(c.runs) + " runs" +
        (c.extra_runs_seconds > 0.0
             ? " (quick renders get more, up to " + std::to_string(c.max_runs) + ")"
             : std::string()) +
        ", in CPU seconds of the whole process (every thread, user and system, as /bin/time sums "
        "them, which is how the thesis timed), because this machine is shared and its other load "
        "moves wall-clock time far more than CPU time; the CSVs also have the wall-clock "
        "seconds. The renders a ratio compares are made in turns (run k of each before run k+1 of "
        "any), within this run. Counts (lights tested, volumes checked) are averages per shading "
        "point, primary and secondary hits alike. The thesis' figures (Appendix B) were measured "
        "on a 300 MHz SUN ULTRA10: compare its ratios and counts, not its seconds.\n\n";
  md +=
      "## Headline: where each target stands\n\n| target | goal | thesis | measured | status "
      "|\n|---|---|---|---|---|\n";
  for (const bench::Section& s : sections) {
    for (const bench::HeadlineRow& r : s.headline) {
      md += "| " + r.target + " | " + r.goal + " | " + r.thesis + " | " + r.measured + " | " +
            r.status + " |\n";
    }
  }
  md += "\nExperiments:";
  for (std::size_t i = 0; i < names.size(); ++i)
    md += std::string(i ? "," : "") + " [" + names[i] + "](#" + names[i] + ")";
  md += ". Each has its CSV (`" + (names.empty() ? std::string("name") : names.front()) +
        ".csv`, ...) next to this file.\n\n";
  for (std::size_t i = 0; i < sections.size(); ++i)
    md += "<a id=\"" + names[i] + "\"></a>\n\n" + sections[i].markdown + "\n";
  app::write_text_file(out_dir + "/results.md", md);
  return sections.size();
}

}  // namespace

int run_bench(const BenchFlags& flags) {
  const BenchOptions options = parse_options(flags);
  const auto started = std::chrono::steady_clock::now();
  // Ctrl-C stops the suite between renders; nothing reaches the output folder unless the whole
  // suite finished (its files are staged, then moved in together).
  const InterruptScope interrupt_scope;
  // The folders this run makes (the output folder and any missing above it), outermost first:
  // a run that does not finish removes them again, when empty (never anything else's).
  std::vector<fs::path> made;
  std::error_code ec;
  for (fs::path p = fs::absolute(fs::path(options.out));
       !p.empty() && p != p.parent_path() && !fs::exists(fs::symlink_status(p, ec));
       p = p.parent_path()) {
    made.insert(made.begin(), p);
  }
  const auto remove_made = [&made] {
    std::error_code ignored;
    for (auto it = made.rbegin(); it != made.rend(); ++it) fs::remove(*it, ignored);
  };
  for (const fs::path& folder : made) {
    if (!ec) fs::create_directory(folder, ec);
  }
  // A fresh staging folder (mkdtemp): one left by a killed run of the same process id (ids repeat,
  // in a container from run to run) must not lend its files to this run's results.
  std::string staging =
      options.out + "/.levrt-bench-" + std::to_string(static_cast<long>(::getpid())) + "-XXXXXX";
  if (!ec && ::mkdtemp(staging.data()) == nullptr) ec.assign(errno, std::generic_category());
  if (ec) {
    remove_made();
    throw UsageError("--out: cannot make a folder in it (" + ec.message() + "), got '" +
                     options.out + "'");
  }
  std::size_t experiments = 0;
  try {
    experiments = run_suite(options, staging, options.out);
    InterruptScope::throw_if_interrupted();
    app::publish_staging_folder(staging, options.out);
  } catch (...) {
    app::discard_staging_folder(staging);
    remove_made();
    throw;
  }

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf("levrt bench: wrote %s/results.md and %zu experiments' CSVs and plots in %.0f s\n",
              scenes::escape_control_characters(options.out).c_str(), experiments, seconds);
  return 0;
}

}  // namespace app
