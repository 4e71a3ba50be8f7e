// `pathref conform --exec "CMD" [--rules GLOB,...] [DIR]`: runs the golden vectors through
// another implementation over a versioned JSON-lines protocol (spec/conform.md) and judges each
// answer as the library's runner does (golden::judge).
#include <fcntl.h>
#include <fmt/core.h>
#include <fnmatch.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/core/version.hpp"
#include "pathref/core/error.hpp"
#include "pathref/golden/runner.hpp"

namespace pathref::cli {

namespace {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

/// Longest response line accepted (a larger one is reported, not buffered).
constexpr std::size_t max_response_bytes = io::answer_limits.max_bytes;  ///< one answer line (spec/conform.md)
/// An answer longer than this is shown in the report as an excerpt (answer_excerpt).
constexpr std::size_t max_shown_answer = 400;

/// A long or unreadable answer as the report shows it: its first max_shown_answer bytes (control and
/// non-ASCII bytes escaped) and its size; where it first differs is in the case's `why`.
Json answer_excerpt(const std::string& reply) {
  if (reply.size() <= max_shown_answer) return Json(io::printable(reply, max_shown_answer));
  return Json(io::printable(reply, max_shown_answer) + " (" + std::to_string(reply.size()) + " bytes in all)");
}

/// The user's program: `/bin/sh -c CMD` in its own process group, stdin/stdout piped, stderr
/// inherited. Every wait is bounded; the group is killed when the session ends.
class Program {
 public:
  explicit Program(const std::string& command) {
    int in[2], out[2];
    if (pipe(in) != 0 || pipe(out) != 0) throw UsageError(std::string("conform: pipe: ") + std::strerror(errno));
    pid_ = fork();
    if (pid_ < 0) throw UsageError(std::string("conform: fork: ") + std::strerror(errno));
    if (pid_ == 0) {
      setpgid(0, 0);
      dup2(in[0], 0);
      dup2(out[1], 1);
      close(in[0]);
      close(in[1]);
      close(out[0]);
      close(out[1]);
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    setpgid(pid_, pid_);
    close(in[0]);
    close(out[1]);
    to_ = in[1];
    from_ = out[0];
    fcntl(to_, F_SETFL, fcntl(to_, F_GETFL) | O_NONBLOCK);
    fcntl(from_, F_SETFL, fcntl(from_, F_GETFL) | O_NONBLOCK);
  }
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  ~Program() { finish(std::chrono::milliseconds(0)); }

  /// Sends one line; false (with `why`) when the program does not take it in time or has gone.
  bool send(const std::string& line, std::chrono::milliseconds timeout, std::string& why) {
    const std::string data = line + "\n";
    std::size_t done = 0;
    const auto deadline = Clock::now() + timeout;
    while (done < data.size()) {
      const ssize_t n = write(to_, data.data() + done, data.size() - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
        continue;
      }
      if (n < 0 && errno != EAGAIN && errno != EINTR) {
        why = std::string("cannot write to the program: ") + std::strerror(errno);
        return false;
      }
      if (!wait_fd(to_, POLLOUT, deadline)) {
        why = "the program did not read its input in time";
        return false;
      }
    }
    return true;
  }

  /// Receives one line; nullopt (with `why`) on timeout, end of output or an overlong line.
  std::optional<std::string> receive(std::chrono::milliseconds timeout, std::string& why) {
    const auto deadline = Clock::now() + timeout;
    for (;;) {
      const std::size_t nl = buffer_.find('\n');
      if (nl != std::string::npos) {
        std::string line = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1);
        return line;
      }
      if (buffer_.size() > max_response_bytes) {
        why = fmt::format("a response line longer than {} bytes", max_response_bytes);
        return std::nullopt;
      }
      char chunk[65536];
      const ssize_t n = read(from_, chunk, sizeof chunk);
      if (n > 0) {
        buffer_.append(chunk, static_cast<std::size_t>(n));
        continue;
      }
      if (n == 0) {
        why = "the program closed its output (" + exit_status(std::chrono::milliseconds(500)) + ")";
        return std::nullopt;
      }
      if (errno != EAGAIN && errno != EINTR) {
        why = std::string("cannot read from the program: ") + std::strerror(errno);
        return std::nullopt;
      }
      if (!wait_fd(from_, POLLIN, deadline)) {
        why = fmt::format("no answer within {} s", static_cast<double>(timeout.count()) / 1000.0);
        return std::nullopt;
      }
    }
  }

  /// Closes the program's input, waits up to `grace` for it to exit, then kills its process group.
  void finish(std::chrono::milliseconds grace) {
    if (pid_ <= 0) return;
    if (to_ >= 0) close(to_);
    to_ = -1;
    (void)exit_status(grace);
    if (pid_ > 0) {
      kill(-pid_, SIGKILL);
      int st = 0;
      waitpid(pid_, &st, 0);
      pid_ = -1;
    }
    if (from_ >= 0) close(from_);
    from_ = -1;
  }

 private:
  static bool wait_fd(int fd, short events, Clock::time_point deadline) {
    for (;;) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return false;
      pollfd p{fd, events, 0};
      const int r = poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
      if (r > 0) return true;
      if (r < 0 && errno != EINTR) return false;
    }
  }

  /// "exit status N", "killed by signal N" or "still running", waiting up to `grace`.
  std::string exit_status(std::chrono::milliseconds grace) {
    if (pid_ <= 0) return status_;
    const auto deadline = Clock::now() + grace;
    for (;;) {
      int st = 0;
      const pid_t r = waitpid(pid_, &st, WNOHANG);
      if (r == pid_) {
        kill(-pid_, SIGKILL);  // anything the shell left behind
        pid_ = -1;
        status_ = WIFEXITED(st) ? fmt::format("exit status {}", WEXITSTATUS(st))
                                : fmt::format("killed by signal {}", WTERMSIG(st));
        return status_;
      }
      if (Clock::now() >= deadline) return "still running";
      usleep(10000);
    }
  }

  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
  std::string buffer_;
  std::string status_ = "not started";
};

struct ConformOptions {
  std::string exec;
  std::string rules = "*";
  std::string dir = "golden";
  double timeout = 10.0;
  bool json = false;
  std::string json_out;
};

bool rule_selected(const std::string& id, const std::string& globs) {
  std::size_t at = 0;
  for (;;) {
    const std::size_t comma = globs.find(',', at);
    const std::string g = globs.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    if (!g.empty() && fnmatch(g.c_str(), id.c_str(), 0) == 0) return true;
    if (comma == std::string::npos) return false;
    at = comma + 1;
  }
}

struct Tally {
  std::size_t pass = 0, fail = 0, skip = 0;
};

int run_conform(const ConformOptions& o) {
  if (o.exec.empty()) throw UsageError("--exec needs a command");
  if (!(o.timeout > 0.0 && o.timeout <= 3600.0)) throw UsageError("--timeout expects seconds in (0, 3600]");
  const auto timeout = std::chrono::milliseconds(static_cast<long long>(o.timeout * 1000.0));
  // Every file is read and checked before the program starts (bad input: exit 2).
  struct Doc {
    std::string file;
    Json doc;
  };
  std::vector<Doc> docs;
  for (const auto& p : golden::golden_files(o.dir)) {
    Json d = golden::read_document(p);
    if (rule_selected(d.at("rule").get<std::string>(), o.rules)) docs.push_back({p.string(), std::move(d)});
  }
  if (docs.empty()) throw UsageError("--rules '" + o.rules + "' selects no golden file in '" + o.dir + "'");

  signal(SIGPIPE, SIG_IGN);
  Program prog(o.exec);
  std::string why;
  std::optional<std::string> fatal;  // the program failed the session: every later vector fails
  std::optional<Json> implemented;   // the hello's "rules", when given
  const Json hello{{"protocol", "pathref-conform"}, {"version", 1}, {"pathref_version", std::string(pathref::version())}};
  std::optional<std::string> reply;
  if (prog.send(hello.dump(), timeout, why) && (reply = prog.receive(timeout, why))) {
    Json h;
    try {
      h = io::parse_json_text(*reply, "the program's hello", 1, io::answer_limits);
    } catch (const ParseError&) {
      h = Json();
    }
    if (!h.is_object() || h.value("protocol", Json()) != "pathref-conform" ||
        h.value("version", Json()) != 1)
      fatal = "the program's first line is not the hello {\"protocol\": \"pathref-conform\", \"version\": 1}: " +
              io::printable(*reply, 200);
    else if (h.contains("rules"))
      implemented = h.at("rules");
  } else {
    fatal = "no hello: " + why;
  }

  std::map<std::string, Tally> tally;
  Json cases = Json::array();
  Json first_failure;
  long long id = 0;
  for (const Doc& d : docs) {
    const std::string rule = d.doc.at("rule").get<std::string>();
    Tally& t = tally[rule];
    bool rule_implemented = true;
    if (implemented && implemented->is_array()) {
      rule_implemented = false;
      for (const Json& r : *implemented) rule_implemented = rule_implemented || r == rule;
    }
    for (const Json& group : d.doc.at("testGroups"))
      for (const Json& test : group.at("tests")) {
        Json c{{"file", d.file}, {"rule", rule}, {"tcId", test.at("tcId")}};
        if (!rule_implemented) {
          ++t.skip;
          c["status"] = "skip";
          c["why"] = "rule not implemented (not in the hello's rules)";
          cases.push_back(std::move(c));
          continue;
        }
        Json request{{"id", ++id}, {"rule", rule}, {"input", golden::compose_input(d.doc, group, test)}};
        if (test.contains("interpretation")) request["interpretation"] = test.at("interpretation");
        std::string status = "fail", message;
        Json got = nullptr;
        if (fatal) {
          message = "not run: " + *fatal;
        } else if (!prog.send(request.dump(), timeout, why) || !(reply = prog.receive(timeout, why))) {
          fatal = why;
          message = why;
        } else {
          std::optional<std::string> refused;
          try {
            got = io::parse_json_text(*reply, "the answer", 1, io::answer_limits);
          } catch (const ParseError& e) {
            refused = e.what();
          }
          if (refused) {
            message = "the answer is not a JSON object: " + io::printable(*reply, 200) + " (" +
                      io::printable(*refused, 300) + ")";
            got = answer_excerpt(*reply);
          } else if (!got.is_object()) {
            message = "the answer is not a JSON object: " + io::printable(*reply, 200);
            got = answer_excerpt(*reply);
          } else if (got.value("id", Json()) != request.at("id")) {
            message = "the answer's id is " + got.value("id", Json()).dump() + ", expected " + request.at("id").dump();
            fatal = "out of step: " + message;
          } else if (got.contains("skip")) {
            status = "skip";
            message = got.at("skip").is_string() ? got.at("skip").get<std::string>() : got.at("skip").dump();
          } else if (got.contains("error")) {
            Json actual{{"error", got.at("error")},
                        {"message", got.contains("message") && got.at("message").is_string() ? got.at("message") : Json("")}};
            message = golden::judge(group, test, actual);
            if (message.empty()) status = "pass";
          } else if (got.contains("output") && got.at("output").is_object()) {
            message = golden::judge(group, test, got.at("output"));
            if (message.empty()) status = "pass";
          } else {
            message = "the answer has none of output (an object), error, skip";
          }
        }
        if (status == "pass") ++t.pass;
        else if (status == "skip") ++t.skip;
        else ++t.fail;
        c["status"] = status;
        if (!message.empty()) c["why"] = message;
        if (status == "fail" && first_failure.is_null())
          first_failure = Json{{"file", d.file},     {"rule", rule},         {"tcId", test.at("tcId")},
                               {"comment", test.value("comment", "")},     {"request", request},
                               {"expected", test.at("expected")},          {"result", test.at("result")},
                               {"answer", reply && reply->size() > max_shown_answer ? answer_excerpt(*reply) : got},
                               {"why", message}};
        cases.push_back(std::move(c));
      }
  }
  prog.finish(std::chrono::milliseconds(2000));

  Tally total;
  Json rules_json = Json::object();
  for (const auto& [rule, t] : tally) {
    total.pass += t.pass;
    total.fail += t.fail;
    total.skip += t.skip;
    rules_json[rule] = {{"pass", t.pass}, {"fail", t.fail}, {"skip", t.skip}};
  }
  Json doc{{"format", "pathref-conform-report"},
                 {"format_version", 1},
                 {"exec", o.exec},
                 {"golden", o.dir},
                 {"rules_glob", o.rules},
                 {"program_failure", fatal ? Json(*fatal) : Json(nullptr)},
                 {"total", {{"pass", total.pass}, {"fail", total.fail}, {"skip", total.skip}}},
                 {"rules", rules_json},
                 {"first_failure", first_failure},
                 {"cases", cases}};
  stamp_version(doc);
  if (!o.json_out.empty()) write_output_file(o.json_out, doc.dump(2) + "\n");
  if (o.json) {
    fmt::print("{}\n", doc.dump(2));
  } else {
    fmt::print("pathref {} conform: {} on {}\n", std::string(pathref::version()), o.exec, o.dir);
    fmt::print("{:<40} {:>6} {:>6} {:>6}\n", "rule", "pass", "fail", "skip");
    for (const auto& [rule, t] : tally) fmt::print("{:<40} {:>6} {:>6} {:>6}\n", rule, t.pass, t.fail, t.skip);
    fmt::print("{:<40} {:>6} {:>6} {:>6}\n", "total", total.pass, total.fail, total.skip);
    if (fatal) fmt::print("program failure: {}\n", *fatal);
    if (!first_failure.is_null()) fmt::print("first failing vector:\n{}\n", first_failure.dump(2));
    if (!o.json_out.empty()) fmt::print("wrote {}\n", o.json_out);
  }
  return total.fail == 0 && total.pass > 0 ? 0 : 1;
}

}  // namespace

void add_conform_command(CLI::App& app, Action& run) {
  static ConformOptions o;
  auto* cmd = app.add_subcommand(
      "conform", "Run the golden vectors through another implementation over JSON lines (spec/conform.md)");
  cmd->add_option("--exec", o.exec, "the program, run once with /bin/sh -c (it reads requests on stdin)")
      ->type_name("CMD")
      ->required();
  cmd->add_option("--rules", o.rules, "only the rules matching these comma-separated globs (e.g. 'grid.*,metrics.length')")
      ->type_name("GLOB,...")
      ->capture_default_str();
  cmd->add_option("--timeout", o.timeout, "seconds to wait for each answer (0 < T <= 3600)")->capture_default_str();
  cmd->add_flag("--json", o.json, "print the JSON report instead of the table");
  cmd->add_option("--json-out", o.json_out, "also write the JSON report to FILE")->type_name("FILE");
  cmd->add_option("dir", o.dir, "golden folder (default: ./golden of the working directory)")->capture_default_str();
  cmd->callback([&run] { run = [] { return run_conform(o); }; });
}

}  // namespace pathref::cli
