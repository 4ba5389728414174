#pragma once
/// @file ReadProbeCsv: named columns of a probes.csv file (as ProbeCsvWriter writes it) over a
/// time window.

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "ancfnet/common/types.hpp"

namespace ancfnet {

/// Columns read from a probe CSV file.
struct ProbeSeries {
  std::vector<std::string> columns;  ///< the names read, in the order asked for
  VectorXd time;                     ///< s, strictly increasing, one per row
  MatrixXd values;                   ///< one row per time, one column per name (SI units)
};

/// The time window of ReadProbeCsv: rows with from ≤ time ≤ to (s).
struct ProbeCsvWindow {
  double from = -std::numeric_limits<double>::infinity();
  double to = std::numeric_limits<double>::infinity();
};

/// Reads the columns `columns` (names as in the header, e.g. "tip.z"; empty: every column but
/// time) of the CSV file `path`, whose header is `time,NAME.COMPONENT,…` and whose rows hold
/// numbers (ProbeCsvWriter's format; spaces around fields and CRLF line ends are accepted), keeping
/// the rows with window.from ≤ time ≤ window.to.
/// Throws InputError naming the file: cannot be opened; no header or a first column other than
/// `time`; a column not in the header ("no column 'tip.q'; did you mean 'tip.z'?", then the
/// columns there are); a row with a different number of fields, a field that is not a finite
/// number, or a time that does not increase (naming the line); no row in the window (giving the
/// file's time span); from > to.
ProbeSeries ReadProbeCsv(const std::filesystem::path& path, const std::vector<std::string>& columns,
                         const ProbeCsvWindow& window = {});

}  // namespace ancfnet
