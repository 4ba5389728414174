#include "results.hpp"

#include <fmt/format.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/probe_csv_reader.hpp"
#include "array_view.hpp"

namespace py = pybind11;

namespace ancfnet::python {

py::dict ReadSummary(const std::filesystem::path& output_dir) {
  const std::filesystem::path path = output_dir / "summary.json";
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  if (!file) throw InputError(fmt::format("{}: cannot read the run's summary", path.string()));
  return py::module_::import("json").attr("loads")(text.str());
}

py::dict ReadProbes(const std::filesystem::path& path) {
  auto series = std::make_unique<ProbeSeries>(ReadProbeCsv(path, {}));
  const ProbeSeries& s = *series;
  const py::capsule owner(series.release(), [](void* p) { delete static_cast<ProbeSeries*>(p); });
  py::dict columns;
  columns["time"] = ReadOnlyView(s.time.data(), s.time.size(), owner);
  for (std::size_t c = 0; c < s.columns.size(); ++c)
    columns[py::str(s.columns[c])] =
        ReadOnlyView(s.values.col(static_cast<Index>(c)).data(), s.values.rows(), owner);
  return columns;
}

}  // namespace ancfnet::python
