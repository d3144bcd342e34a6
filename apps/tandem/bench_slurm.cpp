#include "bench_slurm.hpp"

#include "process.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"

namespace tandem::cli {
namespace {

/// sbatch's lines as one ("a; b").
std::string one_line(const std::string& text) {
  std::string line;
  for (const char c : trim(text))
    line += c == '\n' ? std::string("; ") : std::string(1, c);
  return line;
}

/// Runs sbatch --parsable with these arguments and returns the job id.
std::string sbatch(std::vector<std::string> args) {
  args.insert(args.begin(), {"sbatch", "--parsable"});
  const ProcessResult r = run_process(args);
  if (!r.found)
    throw InputError("--slurm", "sbatch was not found on PATH: run this on a Slurm login node");
  const std::string id = parsable_job_id(trim(r.output));
  if (r.exit_code != 0 || id.empty())
    throw InputError("--slurm", "sbatch refused the job: " + one_line(r.output));
  return id;
}

bool has_any(const std::string& text, const char* chars) {
  return text.find_first_of(chars) != std::string::npos;
}

}  // namespace

void check_slurm_sweep(const SlurmSweep& sweep) {
  if (has_any(sweep.out_dir.string(), " \t\n\r'\"\\%"))
    throw InputError("--out",
                     "a folder for Slurm jobs must have a path without blanks, quotes, "
                     "backslashes or '%', not '" +
                         sweep.out_dir.string() + "'");
  if (has_any(sweep.partition, " \t\n\r"))
    throw InputError("--partition", "must be one word, not '" + sweep.partition + "'");
  for (const std::string& a : sweep.sbatch_args) {
    if (has_any(a, "\n\r") || a.rfind("--", 0) != 0)
      throw InputError("--sbatch",
                       "must be one sbatch option such as --time=2:00:00, not '" + a + "'");
  }
}

void submit_sweep(const SlurmSweep& sweep, const std::vector<unsigned>& shards,
                  unsigned retries_left, std::ostream& out) {
  const std::filesystem::path dir = sweep.out_dir / "slurm";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError(dir.string(), "cannot be created as a folder");
  write_file_atomically(dir / "array.sbatch", array_script(sweep, shards));
  write_file_atomically(dir / "merge.sbatch", merge_script(sweep, retries_left));
  const std::string array = sbatch({(dir / "array.sbatch").string()});
  const std::string merge = sbatch({"--dependency=afterany:" + array, "--kill-on-invalid-dep=no",
                                    (dir / "merge.sbatch").string()});
  out << "submitted job array " << array << " (shards " << array_spec(shards) << " of "
      << sweep.tasks << ") and merge job " << merge << " after it\n"
      << "follow with: squeue -j " << array << ',' << merge << "\n"
      << "task logs: " << dir.string() << "/\n"
      << "when the merge job ends: " << (sweep.out_dir / "report.md").string() << '\n';
}

}  // namespace tandem::cli
