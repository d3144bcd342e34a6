// tandem export: a path as an animation anyone can open (.glb, or one offline .html page), and the
// part's motion envelope (.stl, and in the animation).

#include <malloc.h>

#include <fstream>
#include <iostream>
#include <optional>

#include "cli_support.hpp"
#include "commands.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/core/text.hpp"
#include "tandem/export/motion_envelope.hpp"
#include "tandem/export/path_animation.hpp"
#include "tandem/export/player_page.hpp"
#include "tandem/export/stl_file.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/web/viewer_server.hpp"

namespace tandem::cli {
namespace {

struct ExportArgs {
  ProblemArgs problem;
  std::string path_file;
  std::string glb, html, stl;
  bool envelope = false;
  double voxel = 0.0;
  double duration = 10.0;
  std::string title;
};

void write_file(const std::string& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary);
  if (!out || !out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())).flush())
    throw InputError(file, "cannot be written");
}

/// The built player script (scripts/build-web), from the viewer's web root.
std::string player_script() {
  std::optional<std::string> script = read_player_script(default_web_root());
  if (!script)
    throw InputError((default_web_root() / "player" / "player.js").string(),
                     "the animation player is not built (run scripts/build-web)");
  return std::move(*script);
}

MotionEnvelope envelope_of(const Problem& problem, const Path& path, double voxel) {
  // OpenVDB allocates and frees a few large nodes for each pose; without this, glibc maps each
  // from the kernel again (mmap above 128 KiB), which more than doubles the time.
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  const Body& object = problem.scene.object;
  const Stopwatch watch;
  MotionEnvelope e = motion_envelope(object, path, problem.space,
                                     voxel > 0 ? voxel : default_envelope_voxel(object));
  std::cout << "envelope: " << e.poses << " poses of the part, voxel " << e.voxel << ", "
            << e.mesh.triangle_count() << " triangles; contains the part along the whole "
            << "motion, at most " << e.offset << " outside it (" << watch.seconds() << " s)\n";
  return e;
}

int run_export(const ExportArgs& args) {
  if (args.glb.empty() && args.html.empty() && args.stl.empty())
    throw InputError("tandem export", "nothing to write: give --glb, --html or --stl");
  const Problem problem = load_problem(args.problem);
  const Path path = read_path_file(args.path_file, problem.space);
  const std::string script = args.html.empty() ? "" : player_script();
  std::optional<MotionEnvelope> envelope;
  if (args.envelope || !args.stl.empty())
    envelope = envelope_of(problem, path, args.voxel);
  if (!args.stl.empty()) {
    write_stl(envelope->mesh, args.stl, "tandem motion envelope of " + problem.name);
    std::cout << "wrote " << args.stl << '\n';
  }
  if (args.glb.empty() && args.html.empty())
    return 0;
  AnimationOptions options;
  options.duration = args.duration;
  options.envelope = args.envelope ? &envelope->mesh : nullptr;
  options.title = args.title.empty() ? problem.name + ": " +
                                           std::filesystem::path(args.path_file).filename().string()
                                     : args.title;
  const std::string glb = path_animation_glb(problem.scene, path, problem.space, options);
  for (const auto& [file, bytes] :
       {std::pair{args.glb, glb}, std::pair{args.html, player_page(glb, script, options.title)}})
    if (!file.empty()) {
      write_file(file, bytes);
      std::cout << "wrote " << file << " (" << bytes.size()
                << " bytes): " << problem.scene.obstacles.size() << " obstacles, the part along "
                << path.size() << " states over " << args.duration << " s\n";
    }
  return 0;
}

}  // namespace

Command add_export_command(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  add_problem_args(app, args->problem);
  add_path_file_arg(app, args->path_file);
  app.add_option("--glb", args->glb,
                 "Write the scene and the part moving along the path as an animated glTF 2.0 "
                 "binary (three.js, Blender, model viewers)");
  app.add_option("--html", args->html,
                 "Write one self-contained page that plays it offline: orbit camera, play, "
                 "scrubber");
  app.add_option("--stl", args->stl,
                 "Write the part's motion envelope (the volume it sweeps) as binary STL");
  app.add_flag("--envelope", args->envelope, "Put the motion envelope in the animation");
  app.add_option("--voxel", args->voxel,
                 "The envelope's voxel size (0: the part's largest extent / 48); the envelope "
                 "contains every pose of the part and lies within about 2.3 voxels of it")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--duration", args->duration,
                 "Seconds the animation lasts (the part moves at constant speed)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--title", args->title, "The animation's title (default: problem: path file)");
  return [args]() { return run_export(*args); };
}

}  // namespace tandem::cli
