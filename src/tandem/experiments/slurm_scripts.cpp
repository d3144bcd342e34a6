#include "tandem/experiments/slurm_scripts.hpp"

#include <cctype>
#include <sstream>

namespace tandem {
namespace {

/// The #SBATCH lines every job of the sweep shares.
void common_options(std::ostringstream& s, const SlurmSweep& sweep) {
  if (!sweep.partition.empty())
    s << "#SBATCH --partition=" << sweep.partition << '\n';
  for (const std::string& a : sweep.sbatch_args)
    s << "#SBATCH " << a << '\n';
}

/// `tandem bench EXPERIMENT --out OUT` and the sweep's own options, quoted for bash.
std::string bench_command(const SlurmSweep& sweep) {
  std::string c = shell_quote(sweep.tandem.string()) + " bench " +
                  shell_quote(sweep.experiment.string()) + " --out " +
                  shell_quote(sweep.out_dir.string());
  for (const std::string& a : sweep.bench_args)
    c += " " + shell_quote(a);
  return c;
}

std::string log_dir(const SlurmSweep& sweep) {
  return (sweep.out_dir / "slurm").string();
}

}  // namespace

std::string array_script(const SlurmSweep& sweep, const std::vector<unsigned>& shards) {
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# tandem bench --slurm: shard K of " << sweep.tasks << " of experiment " << sweep.name
    << " (K = the array task)\n"
    << "#SBATCH --job-name=tandem-" << sweep.name << '\n'
    << "#SBATCH --array=" << array_spec(shards) << '\n'
    << "#SBATCH --ntasks=1\n"
    << "#SBATCH --cpus-per-task=" << sweep.cpus_per_task << '\n'
    << "#SBATCH --output=" << log_dir(sweep) << "/shard-%a-of-" << sweep.tasks << "-%A.out\n";
  common_options(s, sweep);
  s << "set -eu\n"
    << "exec " << bench_command(sweep) << " --shard \"$SLURM_ARRAY_TASK_ID/" << sweep.tasks
    << "\" --jobs \"${SLURM_CPUS_PER_TASK:-" << sweep.cpus_per_task << "}\" --quiet\n";
  return s.str();
}

std::string merge_script(const SlurmSweep& sweep, unsigned retries_left) {
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# tandem bench --slurm: merges the " << sweep.tasks << " shards of experiment "
    << sweep.name << ", writes the report, re-submits failed shards (" << retries_left
    << " round(s) left)\n"
    << "#SBATCH --job-name=tandem-" << sweep.name << "-merge\n"
    << "#SBATCH --ntasks=1\n"
    << "#SBATCH --cpus-per-task=1\n"
    << "#SBATCH --output=" << log_dir(sweep) << "/merge-%j.out\n";
  common_options(s, sweep);
  s << "set -eu\n"
    << "exec " << bench_command(sweep) << " --merge --slurm --tasks " << sweep.tasks
    << " --cpus-per-task " << sweep.cpus_per_task << " --retries " << retries_left;
  if (!sweep.partition.empty())
    s << " --partition " << shell_quote(sweep.partition);
  for (const std::string& a : sweep.sbatch_args)
    s << " --sbatch " << shell_quote(a);
  s << '\n';
  return s.str();
}

std::string array_spec(const std::vector<unsigned>& shards) {
  std::string spec;
  for (std::size_t i = 0; i < shards.size();) {
    std::size_t j = i;
    while (j + 1 < shards.size() && shards[j + 1] == shards[j] + 1)
      ++j;
    if (!spec.empty())
      spec += ',';
    spec += std::to_string(shards[i]);
    if (j > i)
      spec += "-" + std::to_string(shards[j]);
    i = j + 1;
  }
  return spec;
}

std::string shell_quote(std::string_view word) {
  std::string q = "'";
  for (const char c : word) {
    if (c == '\'') {
      q += "'\\''";
    } else {
      q += c;
    }
  }
  return q + "'";
}

std::string parsable_job_id(std::string_view answer) {
  std::size_t n = 0;
  while (n < answer.size() && std::isdigit(static_cast<unsigned char>(answer[n])) != 0)
    ++n;
  return std::string(answer.substr(0, n));
}

}  // namespace tandem
