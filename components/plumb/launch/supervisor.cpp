#include "supervisor.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "child.hpp"
#include "plumb/components/cli.hpp"

namespace plumb::launch {
namespace {

using Clock = std::chrono::steady_clock;

enum class State { Running, Waiting, Done, Failed };

struct Slot {
  const ProgramSpec* spec;
  std::string path;
  std::unique_ptr<Child> child;
  State state = State::Waiting;
  int restarts = 0;
  Clock::time_point start_at{};
};

std::string describe_status(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    const char* name = ::sigabbrev_np(WTERMSIG(status));
    return std::string("killed by SIG") + (name ? name : std::to_string(WTERMSIG(status)));
  }
  return "status " + std::to_string(status);
}

class Supervisor {
 public:
  Supervisor(const std::vector<ProgramSpec>& programs, SupervisorOptions options, std::ostream& out, std::ostream& err)
      : options_(options), out_(out), err_(err) {
    for (const auto& p : programs) {
      const std::string path = find_program(p.argv[0]);
      if (path.empty())
        throw std::invalid_argument((p.cmd_where.empty() ? p.where : p.cmd_where) + ": program '" + p.argv[0] +
                                    "' not found (next to plumb, nor on PATH)");
      slots_.push_back({&p, path, nullptr, State::Waiting, 0, Clock::now()});
    }
  }

  int run() {
    while (true) {
      if (components::g_stop && !stopping_) begin_stop("stop asked (SIGINT/SIGTERM)");
      start_due();
      pump(100);
      reap();
      if (all_ended()) break;
      if (stopping_ && Clock::now() > kill_at_) kill_remaining();
    }
    std::string alone;
    for (const auto& why : failed_alone_) alone += (alone.empty() ? "" : "; ") + why;
    if (failed_) {
      say("launch", "stopped: " + failed_what_ + (alone.empty() ? "" : "; failed alone before: " + alone));
    } else {
      say("launch", alone.empty() ? "every program ended" : "every program ended; failed alone: " + alone);
    }
    return failed_ || !alone.empty() ? 1 : 0;
  }

 private:
  void say(const std::string& who, const std::string& text) { out_ << "[" << who << "] " << text << std::endl; }

  void start_due() {
    if (stopping_) return;
    for (auto& s : slots_) {
      if (s.state != State::Waiting || Clock::now() < s.start_at) continue;
      try {
        s.child = std::make_unique<Child>(s.path, s.spec->argv, s.spec->env, s.spec->cwd);
        s.state = State::Running;
        say("launch", "started " + s.spec->name + " (pid " + std::to_string(s.child->pid()) + "): " + command_line(*s.spec));
      } catch (const std::exception& e) {
        say("launch", s.spec->name + ": " + e.what());
        failed_for_good(s, s.spec->name + " could not be started");
      }
    }
  }

  static std::string command_line(const ProgramSpec& p) {
    std::string text;
    for (const auto& a : p.argv) text += (text.empty() ? "" : " ") + a;
    return text;
  }

  // Copies every output line there is, prefixed, waiting at most `timeout_ms` for one.
  void pump(int timeout_ms) {
    std::vector<pollfd> fds;
    std::vector<Slot*> owners;
    for (auto& s : slots_) {
      if (!s.child) continue;
      for (int fd : s.child->fds()) {
        fds.push_back({fd, POLLIN, 0});
        owners.push_back(&s);
      }
    }
    if (fds.empty()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms));
      return;
    }
    if (::poll(fds.data(), fds.size(), timeout_ms) <= 0) return;
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].revents == 0) continue;
      const std::string& name = owners[i]->spec->name;
      owners[i]->child->read(fds[i].fd, [&](const std::string& line, bool is_err) {
        (is_err ? err_ : out_) << "[" << name << "] " << line << std::endl;
      });
    }
  }

  void reap() {
    for (auto& s : slots_) {
      if (s.state != State::Running) continue;
      int status = 0;
      if (::waitpid(s.child->pid(), &status, WNOHANG) != s.child->pid()) continue;
      // What it wrote just before it ended is still in the pipes (at most 1 s more: a process it
      // started may hold them open).
      for (int i = 0; i < 20 && !s.child->fds().empty(); ++i) pump_child(s);
      s.child.reset();
      ended(s, status);
    }
  }

  void pump_child(Slot& s) {
    for (int fd : s.child->fds()) {
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      s.child->read(fd, [&](const std::string& line, bool is_err) {
        (is_err ? err_ : out_) << "[" << s.spec->name << "] " << line << std::endl;
      });
    }
  }

  void ended(Slot& s, int status) {
    const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    const std::string how = describe_status(status);
    if (stopping_ || ok) {
      s.state = State::Done;
      say("launch", s.spec->name + " ended (" + how + ")");
      if (!stopping_ && s.spec->shutdown_on_exit) begin_stop(s.spec->name + " ended (on_exit: shutdown)");
      return;
    }
    // Exit status 2 is a usage error (every plumb program's): the same command would fail again.
    const bool usage_error = WIFEXITED(status) && WEXITSTATUS(status) == 2;
    if (usage_error) {
      failed_for_good(s, s.spec->name + " failed (" + how + ": a usage error, not restarted; its command is at " +
                             (s.spec->cmd_where.empty() ? s.spec->where : s.spec->cmd_where) + ")");
      return;
    }
    if (s.spec->restart == Restart::OnFailure && s.restarts < s.spec->restart_limit) {
      ++s.restarts;
      s.state = State::Waiting;
      s.start_at = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(s.spec->restart_delay_s));
      std::ostringstream text;
      text << s.spec->name << " failed (" << how << "); restart " << s.restarts << " of " << s.spec->restart_limit
           << " in " << s.spec->restart_delay_s << " s";
      say("launch", text.str());
      return;
    }
    failed_for_good(s, s.spec->restart == Restart::Never
                           ? s.spec->name + " failed (" + how + "; restart: never)"
                           : s.spec->name + " failed (" + how + ") after " + std::to_string(s.restarts) + " restarts");
  }

  // A program the file marks required, or whose end ends the launch (on_exit: shutdown), stops the
  // others; any other fails alone (a display whose port is taken does not stop the survey).
  void failed_for_good(Slot& s, const std::string& why) {
    s.state = State::Failed;
    if (s.spec->required || s.spec->shutdown_on_exit) {
      say("launch", why + (s.spec->required ? " (required)" : " (on_exit: shutdown)") + ": stopping the others");
      fail(why);
      return;
    }
    say("launch", why + ": the others go on (not required)");
    failed_alone_.push_back(why);
  }

  void fail(const std::string& why) {
    if (!failed_) failed_what_ = why;
    failed_ = true;
    begin_stop(why);
  }

  void begin_stop(const std::string& why) {
    if (stopping_) return;
    stopping_ = true;
    kill_at_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options_.stop_timeout_s));
    bool any = false;
    for (auto& s : slots_) {
      if (s.state == State::Waiting) s.state = State::Done;  // a pending restart is dropped
      if (s.state != State::Running) continue;
      s.child->signal(SIGINT);
      any = true;
    }
    if (any) say("launch", why + ": stopping every program (SIGINT; SIGKILL after " +
                               std::to_string(static_cast<int>(options_.stop_timeout_s)) + " s)");
  }

  void kill_remaining() {
    for (auto& s : slots_) {
      if (s.state != State::Running) continue;
      say("launch", s.spec->name + " did not stop within the timeout: SIGKILL");
      s.child->signal(SIGKILL);
    }
    kill_at_ = Clock::now() + std::chrono::hours(1);
  }

  bool all_ended() const {
    for (const auto& s : slots_)
      if (s.state == State::Running || s.state == State::Waiting) return false;
    return true;
  }

  SupervisorOptions options_;
  std::ostream& out_;
  std::ostream& err_;
  std::vector<Slot> slots_;
  bool stopping_ = false;
  bool failed_ = false;
  std::string failed_what_;
  std::vector<std::string> failed_alone_;
  Clock::time_point kill_at_{};
};

}  // namespace

int supervise(const std::vector<ProgramSpec>& programs, const SupervisorOptions& options, std::ostream& out,
              std::ostream& err) {
  return Supervisor(programs, options, out, err).run();
}

}  // namespace plumb::launch
