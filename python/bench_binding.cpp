// tandem.bench: an experiment file run as `tandem bench` runs it (the same runs, resumable, the same
// runs.jsonl, OMPL log and report), or one shard of it; its records come back as Python dicts.
//
// Threading: the runs go on the experiment's worker threads with the GIL released.

#include <pybind11/stl.h>

#include "bench_run.hpp"
#include "conversions.hpp"
#include "module_parts.hpp"
#include "tandem/experiments/merge_shards.hpp"

namespace tandem::python {
namespace {

py::list record_list(const std::vector<RunRecord>& records) {
  py::list out;
  for (const RunRecord& r : records)
    out.append(to_python(record_json(r)));
  return out;
}

py::dict bench(const std::string& experiment, const std::string& out, unsigned jobs,
               std::optional<std::uint64_t> seeds, const std::vector<std::string>& allow_dirs,
               const std::string& shard) {
  cli::BenchRequest request;
  request.experiment = experiment;
  request.out = out;
  request.jobs = jobs;
  request.seeds = seeds;
  request.allowed_dirs = allow_dirs;
  if (!shard.empty())
    request.shard = parse_shard(shard, "shard");
  const cli::LoadedBench loaded = cli::load_bench(request);
  BenchResult result;
  std::optional<ReportFiles> report;
  {
    const py::gil_scoped_release release;
    result = cli::run_bench_runs(loaded, request);
    if (!request.shard)
      report = cli::write_bench_products(loaded, result.records, cli::bench_command_text(request));
  }
  py::dict d;
  d["name"] = loaded.experiment.name;
  d["records"] = record_list(result.records);
  d["planned"] = result.planned;
  d["ran"] = result.ran;
  d["resumed"] = result.resumed;
  d["out"] = loaded.out_dir.string();
  d["runs"] =
      (request.shard ? shard_file(loaded.out_dir, *request.shard) : loaded.out_dir / kRunsFile)
          .string();
  d["report"] = report ? py::object(py::str(report->markdown.string())) : py::object(py::none());
  return d;
}

py::list read_runs(const std::string& file) {
  return record_list(read_records(file));
}

}  // namespace

void define_bench(py::module_& m) {
  m.def("bench", &bench, py::arg("experiment"), py::arg("out") = "", py::arg("jobs") = 0,
        py::arg("seeds") = py::none(), py::arg("allow_dirs") = std::vector<std::string>{},
        py::arg("shard") = "",
        "Runs an experiment file as `tandem bench` does (what OUT/runs.jsonl lacks; jobs 0: one "
        "per core), writes OUT/ompl.log and OUT/report.md, and returns the runs' records (dicts "
        "with config, params, seed, solved, path_valid, time_s, nodes, ...). shard 'K/N' runs "
        "only that share into OUT/shards/ (no report; `tandem bench --merge` joins them)");
  m.def("read_runs", &read_runs, py::arg("file"),
        "The records of a runs file (runs.jsonl, or a shard's), as dicts");
}

}  // namespace tandem::python
