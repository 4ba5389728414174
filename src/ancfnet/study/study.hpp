#pragma once
/// @file A study: a base scene run many times with some of its values varied, on a grid or
/// sampled from distributions with a fixed seed (`ancfnet study`, docs/studies.md).

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ancfnet/study/case_sampling.hpp"
#include "ancfnet/study/scene_path.hpp"

namespace ancfnet {

enum class StudySampling {
  kGrid,            ///< every combination of the parameters' `values`
  kRandom,          ///< `cases` independent draws of every parameter's distribution
  kLatinHypercube,  ///< `cases` draws, each parameter's strata hit once
};

/// One varied value of the base scene.
struct StudyParameter {
  enum class Kind { kValues, kUniform, kNormal };
  ScenePath path;
  Kind kind = Kind::kValues;
  std::vector<double> values;  ///< kValues: the grid's values
  double low = 0.0;            ///< kUniform: [low, high]
  double high = 0.0;
  double mean = 0.0;  ///< kNormal: mean and standard deviation (> 0)
  double standard_deviation = 0.0;

  /// The value at probability u in (0, 1) of the distribution (kUniform, kNormal).
  double Quantile(double u) const;
};

/// A success envelope to draw: `metric` (a column of study.csv) over parameters x and y.
struct StudyPlot {
  std::string x;
  std::string y;
  std::string metric;
};

struct Study {
  std::filesystem::path scene_file;  ///< the base scene
  YAML::Node scene;                  ///< its YAML tree
  StudySampling sampling = StudySampling::kGrid;
  std::size_t sampled_cases = 0;  ///< kRandom, kLatinHypercube
  std::uint64_t seed = 1;
  std::vector<StudyParameter> parameters;
  /// Values set alike in every case (`set:`), e.g. a shorter end time.
  std::vector<std::pair<ScenePath, double>> fixed_values;
  std::optional<StudyPlot> plot;

  /// The parameter values of every case, one row per case.
  CaseTable MakeCases() const;
  /// The base scene with the fixed values and the parameters set to `values`, as YAML text.
  std::string MakeCaseScene(const std::vector<double>& values) const;
};

/// The most cases a study may have.
inline constexpr std::size_t kMaxStudyCases = 100000;

/// Reads the study file `file` and its base scene (`scene`, relative to the study file's
/// folder), which must load as `ancfnet check` loads it. Throws InputError
/// "FILE:LINE:COLUMN: what is wrong (key 'KEY')" for a malformed study: an unknown or missing
/// key, a bad distribution, a path the base scene lacks or that names no number, no cases or
/// more than kMaxStudyCases; and as LoadScene for a bad base scene.
Study LoadStudy(const std::filesystem::path& file);

/// As LoadStudy, from the text of a study file; `source_name` names it in messages and
/// `directory` is the folder its scene is taken from.
Study ParseStudy(const std::string& yaml_text, const std::string& source_name,
                 const std::filesystem::path& directory);

}  // namespace ancfnet
