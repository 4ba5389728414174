#include "identify_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ancfnet/analysis/modal_identification.hpp"
#include "ancfnet/common/error.hpp"
#include "ancfnet/io/probe_csv_reader.hpp"

namespace ancfnet {
namespace {

using Json = nlohmann::ordered_json;

Json ComplexJson(const std::complex<double>& value) {
  return Json{{"real", value.real()}, {"imag", value.imag()}};
}

Json MakeJson(const IdentifyArguments& arguments, const ProbeSeries& series,
              const ModalIdentification& id) {
  Json modes = Json::array();
  for (std::size_t i = 0; i < id.modes.size(); ++i) {
    const IdentifiedMode& m = id.modes[i];
    Json amplitude = Json::object();
    Json phase = Json::object();
    for (std::size_t c = 0; c < series.columns.size(); ++c) {
      amplitude[series.columns[c]] = m.amplitude(static_cast<Index>(c));
      phase[series.columns[c]] = m.phase(static_cast<Index>(c));
    }
    modes.push_back({{"mode", i + 1},
                     {"frequency_hz", m.frequency},
                     {"damping_ratio", m.damping_ratio},
                     {"damped_frequency_hz", m.damped_frequency},
                     {"pole", ComplexJson(m.pole)},
                     {"energy_fraction", m.energy_fraction},
                     {"amplitude", amplitude},
                     {"phase_rad", phase}});
  }
  Json others = Json::array();
  for (const OtherPole& p : id.other_poles)
    others.push_back({{"pole", ComplexJson(p.pole)}, {"energy_fraction", p.energy_fraction}});
  return Json{{"method", "matrix pencil (Hua & Sarkar 1990)"},
              {"file", arguments.probes_csv},
              {"columns", series.columns},
              {"start_time", series.time(0)},
              {"end_time", series.time(series.time.size() - 1)},
              {"samples", id.samples},
              {"time_step", id.time_step},
              {"decimation", id.decimation},
              {"nyquist_frequency_hz", id.nyquist_frequency},
              {"pencil", id.pencil},
              {"model_order", id.model_order},
              {"remove_mean", arguments.remove_mean},
              {"relative_residual", id.relative_residual},
              {"modes", modes},
              {"other_poles", others},
              {"singular_values", id.singular_values}};
}

void PrintTable(const ProbeSeries& series, const ModalIdentification& id, std::FILE* out) {
  fmt::print(out, "{} samples from t = {} s to {} s (Δt = {:.6g} s)", id.samples, series.time(0),
             series.time(series.time.size() - 1), id.time_step);
  if (id.decimation > 1) fmt::print(out, ", means of {} samples", id.decimation);
  fmt::print(out,
             "; Nyquist {:.6g} Hz\nmatrix pencil: L = {}, {} poles, relative residual {:.2g}\n",
             id.nyquist_frequency, id.pencil, id.model_order, id.relative_residual);
  fmt::print(out, "{:>4}  {:>12}  {:>9}", "mode", "f [Hz]", "ζ [%]");
  for (const std::string& column : series.columns) fmt::print(out, "  {:>14}", "A " + column);
  fmt::print(out, "\n");
  for (std::size_t i = 0; i < id.modes.size(); ++i) {
    const IdentifiedMode& m = id.modes[i];
    fmt::print(out, "{:>4}  {:>12.7g}  {:>9.4f}", i + 1, m.frequency, 100.0 * m.damping_ratio);
    for (Index c = 0; c < m.amplitude.size(); ++c) fmt::print(out, "  {:>14.6g}", m.amplitude(c));
    fmt::print(out, "\n");
  }
}

}  // namespace

CLI::App* AddIdentifyCommand(CLI::App& app, IdentifyArguments* arguments) {
  CLI::App* command = app.add_subcommand(
      "identify",
      "Natural frequencies and damping ratios of the modes in a free decay (matrix pencil)");
  command->add_option("probes", arguments->probes_csv, "Probe CSV file (time,NAME.COMPONENT,…)")
      ->required();
  command->add_option("--columns", arguments->columns, "Columns to fit together, e.g. tip.z,tip.x")
      ->required()
      ->delimiter(',');
  command->add_option("--modes", arguments->modes, "Number of modes K")->required();
  command->add_option("--extra-poles", arguments->extra_poles,
                      "Poles fitted beyond the 2K of the modes (default 2K)");
  command->add_option("--from", arguments->from, "Use the rows with time ≥ T (s)");
  command->add_option("--to", arguments->to, "Use the rows with time ≤ T (s)");
  command
      ->add_option("--decimate", arguments->decimation,
                   "Fit the means of blocks of D samples (default: automatic, 1 for up to "
                   "1800 samples)")
      ->check(CLI::PositiveNumber);
  command->add_flag("--remove-mean", arguments->remove_mean,
                    "Subtract each column's mean before the fit");
  command->add_option("-o,--output", arguments->output_json, "Write the modes to this JSON file");
  return command;
}

int RunIdentifyCommand(const IdentifyArguments& arguments, std::FILE* out) {
  ProbeCsvWindow window;
  if (arguments.from) window.from = *arguments.from;
  if (arguments.to) window.to = *arguments.to;
  const ProbeSeries series = ReadProbeCsv(arguments.probes_csv, arguments.columns, window);

  ModalIdentificationOptions options;
  options.modes = arguments.modes;
  options.extra_poles = arguments.extra_poles.value_or(2 * arguments.modes);
  options.remove_mean = arguments.remove_mean;
  if (arguments.decimation) options.decimation = *arguments.decimation;
  options.signal_names = series.columns;
  ModalIdentification id;
  try {
    id = IdentifyModes(series.time, series.values, options);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", arguments.probes_csv, e.what()));
  }
  PrintTable(series, id, out);

  if (!arguments.output_json.empty()) {
    std::ofstream file(arguments.output_json);
    file << MakeJson(arguments, series, id).dump(2) << '\n';
    if (!file) throw InputError(fmt::format("cannot write {}", arguments.output_json));
  }
  return 0;
}

}  // namespace ancfnet
