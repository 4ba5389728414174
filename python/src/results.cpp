#include "results.hpp"

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "ancfnet/common/error.hpp"
#include "ancfnet/io/probe_csv_reader.hpp"

namespace py = pybind11;

namespace ancfnet::python {
namespace {

// A read-only array of `size` doubles at `data`, kept alive by `owner`.
py::array_t<double> ColumnView(const double* data, Index size, const py::object& owner) {
  py::array_t<double> column(static_cast<py::ssize_t>(size), data, owner);
  column.attr("setflags")(py::arg("write") = false);
  return column;
}

}  // namespace

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
  columns["time"] = ColumnView(s.time.data(), s.time.size(), owner);
  for (std::size_t c = 0; c < s.columns.size(); ++c)
    columns[py::str(s.columns[c])] =
        ColumnView(s.values.col(static_cast<Index>(c)).data(), s.values.rows(), owner);
  return columns;
}

}  // namespace ancfnet::python
