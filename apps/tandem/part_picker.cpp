#include "part_picker.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <iostream>
#include <mutex>
#include <thread>

#include "tandem/scene/take_out.hpp"
#include "tandem/web/viewer_server.hpp"

namespace tandem::cli {
namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_pick_signal(int) {
  g_stop.store(true);
}

/// Takes the first valid choice of a part; refuses everything else.
///
/// Threading: handle() on the server's thread; chosen() on any.
class PickControl final : public ViewerControl {
 public:
  explicit PickControl(const Problem& assembly) : assembly_(assembly) {}

  std::optional<std::string> handle(const ClientMessage& m) override {
    if (m.kind != ClientMessage::Kind::take_out)
      return "choose the part to take out first: click it, then 'take it out'";
    for (const Body& body : assembly_.scene.obstacles)
      if (body.name == m.part) {
        const std::lock_guard lock(mutex_);
        if (part_.empty())
          part_ = m.part;
        return std::nullopt;
      }
    return "no part '" + m.part.substr(0, 200) + "' in this assembly";
  }
  InteractionSettings settings() const override { return {}; }
  std::optional<std::filesystem::path> journal() const override { return std::nullopt; }

  std::string chosen() const {
    const std::lock_guard lock(mutex_);
    return part_;
  }

 private:
  const Problem& assembly_;
  mutable std::mutex mutex_;
  std::string part_;
};

std::string token_of(const std::string& url) {
  const auto at = url.find("token=");
  return at == std::string::npos ? std::string() : url.substr(at + 6);
}

}  // namespace

std::optional<std::string> pick_part_in_viewer(const ProblemArgs& problem, ViewerArgs& viewer) {
  const Problem assembly = assembly_problem(problem.problem, problem.take_out);
  ViewerState state(assembly, "pick", true);
  PickControl control(assembly);
  std::string part;
  {
    ViewerServer server(state, control, server_options(viewer));
    std::cout << "tandem interactive: " << assembly.name << " (" << assembly.scene.obstacles.size()
              << " parts)\n  viewer: " << server.url()
              << "  (click the part to take out; Ctrl-C ends)\n"
              << std::flush;
    g_stop.store(false);
    std::signal(SIGINT, on_pick_signal);
    std::signal(SIGTERM, on_pick_signal);
    while ((part = control.chosen()).empty() && !g_stop.load())
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    viewer.port = server.port();
    viewer.token = token_of(server.url());
  }
  if (part.empty())
    return std::nullopt;
  std::cout << "  taking out " << part << '\n' << std::flush;
  return part;
}

}  // namespace tandem::cli
