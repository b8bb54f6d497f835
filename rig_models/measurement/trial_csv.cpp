#include "rig_models/measurement/trial_csv.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <fstream>
#include <optional>
#include <sstream>

#include "rig_models/cases/case_code.hpp"
#include "rig_models/core/rig_error.hpp"
#include "rig_models/measurement/clock_jump.hpp"
#include "rig_models/measurement/csv_cells.hpp"

namespace ccm::rig {
namespace {

namespace fs = std::filesystem;

constexpr std::array<std::string_view, 4> kRequired = {kTimeColumn, kVelocityColumn, kAngleColumn,
                                                       kPressureColumn};

// One physical line of the file with its 1-based number, the line ending removed.
struct Line {
  int number = 0;
  std::string_view text;
};

std::vector<Line> split_lines(std::string_view text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  if (text.starts_with(kBom)) text.remove_prefix(kBom.size());
  std::vector<Line> lines;
  int number = 0;
  while (!text.empty()) {
    const size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    if (line.ends_with('\r')) line.remove_suffix(1);
    lines.push_back({++number, line});
    if (nl == std::string_view::npos) break;
    text.remove_prefix(nl + 1);
  }
  return lines;
}

bool is_blank(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return c == ' ' || c == '\t'; });
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// The positions of the columns the reader uses, by header order.
struct ColumnMap {
  std::vector<std::string> names;  // every header cell, in file order
  std::array<size_t, 4> index{};   // of kRequired
};

std::string column_label(const ColumnMap& columns, size_t i) {
  return fmt::format("column {} ({})", i + 1, columns.names[i]);
}

std::string delimiter_problem(char delimiter) {
  return fmt::format("wrong delimiter '{}' (expected ',')",
                     delimiter == '\t' ? std::string("\\t") : std::string(1, delimiter));
}

class TrialReader {
 public:
  TrialReader(std::string_view text, fs::path source) : source_(std::move(source)) {
    trial_.source = source_;
    lines_ = split_lines(text);
  }

  MeasuredTrial read() {
    size_t i = skip_comments(0);
    if (i == lines_.size()) throw error(0, "", "empty file: no header line and no data rows");
    const int header_line = lines_[i].number;
    const ColumnMap columns = read_header(lines_[i]);
    size_t n_rows = 0;
    for (++i; i < lines_.size(); ++i) {
      const Line& line = lines_[i];
      if (is_blank(line.text)) continue;
      if (line.text.starts_with('#')) {
        read_comment(line);
        continue;
      }
      read_row(line, columns);
      ++n_rows;
    }
    if (n_rows == 0) throw error(header_line, "", "header only: no data rows");
    require_samples(columns, header_line);
    refuse_clock_jump(columns);
    identify_case();
    return std::move(trial_);
  }

 private:
  RigInputError error(int line, std::string_view where, std::string_view problem) const {
    return rig_input_error(source_, line, where, problem);
  }

  // Skips blank and comment lines from i (keeping "key: value" metadata); the next index.
  size_t skip_comments(size_t i) {
    for (; i < lines_.size(); ++i) {
      if (is_blank(lines_[i].text)) continue;
      if (!lines_[i].text.starts_with('#')) break;
      read_comment(lines_[i]);
    }
    return i;
  }

  void read_comment(const Line& line) {
    const std::string_view body = trim(line.text.substr(1));
    const size_t colon = body.find(':');
    if (colon == std::string_view::npos || colon == 0) return;  // a plain comment
    const std::string key(trim(body.substr(0, colon)));
    trial_.metadata[key] = std::string(trim(body.substr(colon + 1)));
    metadata_line_[key] = line.number;
  }

  ColumnMap read_header(const Line& line) {
    ColumnMap columns;
    const std::vector<std::string_view> cells = split_cells(line.text);
    for (size_t c = 0; c < cells.size(); ++c) {
      if (const auto d = foreign_delimiter(cells[c]))
        throw error(line.number, fmt::format("column {}", c + 1), delimiter_problem(*d));
      const std::string name(cells[c]);
      if (std::find(columns.names.begin(), columns.names.end(), name) != columns.names.end())
        throw error(line.number, fmt::format("column {} ({})", c + 1, name),
                    "repeats an earlier column");
      columns.names.push_back(name);
    }
    for (size_t r = 0; r < kRequired.size(); ++r) {
      const auto it = std::find(columns.names.begin(), columns.names.end(), kRequired[r]);
      if (it == columns.names.end())
        throw error(line.number, "header",
                    fmt::format("missing required column '{}' (found: {})", kRequired[r],
                                fmt::join(columns.names, ", ")));
      columns.index[r] = static_cast<size_t>(it - columns.names.begin());
    }
    for (size_t c = 0; c < columns.names.size(); ++c)
      if (std::find(kRequired.begin(), kRequired.end(), columns.names[c]) == kRequired.end())
        trial_.warnings.push_back(fmt::format("{}:{}: {}: unknown column, ignored",
                                              source_.string(), line.number,
                                              column_label(columns, c)));
    return columns;
  }

  void read_row(const Line& line, const ColumnMap& columns) {
    const std::vector<std::string_view> cells = split_cells(line.text);
    for (size_t c = 0; c < cells.size(); ++c)
      if (const auto d = foreign_delimiter(cells[c]))
        throw error(line.number, c < columns.names.size() ? column_label(columns, c) : "",
                    delimiter_problem(*d));
    if (cells.size() != columns.names.size())
      throw error(line.number, "",
                  fmt::format("{} cells, the header has {}", cells.size(), columns.names.size()));
    const double t = read_time(line, columns, cells[columns.index[0]]);
    std::array<TimeSeries*, 3> channels = {&trial_.impactor_velocity_mps,
                                           &trial_.artifact_angle_deg, &trial_.pressure_kpa};
    bool any_sensor = false;
    for (size_t r = 1; r < kRequired.size(); ++r) {
      const size_t c = columns.index[r];
      if (cells[c].empty()) continue;
      channels[r - 1]->t.push_back(t);
      channels[r - 1]->value.push_back(number(line, columns, c, cells[c]));
      any_sensor = true;
    }
    if (!any_sensor)
      throw error(line.number, "",
                  fmt::format("no sensor value at {} s (every sensor cell is empty)", t));
    previous_time_ = t;
    previous_line_ = line.number;
    row_times_.push_back(t);
    row_lines_.push_back(line.number);
  }

  // A forward jump of the clock far beyond the file's sampling interval (clock_jump.hpp).
  void refuse_clock_jump(const ColumnMap& columns) const {
    const auto jump = find_clock_jump(row_times_);
    if (!jump) return;
    const size_t k = jump->row;
    throw error(row_lines_[k], column_label(columns, columns.index[0]),
                fmt::format("time jumps by {:.6g} s, from {} s (line {}) to {} s: {:.3g} times "
                            "the file's median step between rows ({:.3g} s; the limit is {:g} "
                            "times). A logger clock glitch? Correct the timestamps or cut the "
                            "file at the jump",
                            jump->step, row_times_[k - 1], row_lines_[k - 1], row_times_[k],
                            jump->step / jump->median_step, jump->median_step, kClockJumpFactor));
  }

  double read_time(const Line& line, const ColumnMap& columns, std::string_view cell) const {
    const size_t c = columns.index[0];
    if (cell.empty()) throw error(line.number, column_label(columns, c), "empty time cell");
    const double t = number(line, columns, c, cell);
    if (previous_line_ > 0 && t == previous_time_)
      throw error(line.number, column_label(columns, c),
                  fmt::format("time {} s repeats the previous row's (line {})", t, previous_line_));
    if (previous_line_ > 0 && t < previous_time_)
      throw error(line.number, column_label(columns, c),
                  fmt::format("time goes backwards: {} s after {} s (line {})", t, previous_time_,
                              previous_line_));
    return t;
  }

  double number(const Line& line, const ColumnMap& columns, size_t c, std::string_view cell) const {
    const CellNumber n = parse_number_cell(cell);
    if (!n.problem.empty()) throw error(line.number, column_label(columns, c), n.problem);
    return n.value;
  }

  void require_samples(const ColumnMap& columns, int header_line) const {
    const std::array<const TimeSeries*, 3> channels = {
        &trial_.impactor_velocity_mps, &trial_.artifact_angle_deg, &trial_.pressure_kpa};
    for (size_t r = 1; r < kRequired.size(); ++r)
      if (channels[r - 1]->t.empty())
        throw error(header_line, column_label(columns, columns.index[r]), "no value in any row");
  }

  // The case code and trial number from the metadata and the file name <CASE>_t<N>.csv;
  // where both give one they must agree.
  void identify_case() {
    const std::string stem = source_.stem().string();
    const size_t sep = stem.rfind("_t");
    std::optional<std::string> name_case;
    std::optional<int> name_trial;
    if (sep != std::string::npos && is_case_code(stem.substr(0, sep))) {
      name_case = stem.substr(0, sep);
      name_trial = positive_int(stem.substr(sep + 2));
    }
    const auto meta_case = metadata("case");
    if (meta_case && !is_case_code(*meta_case))
      throw error(
          metadata_line_.at("case"), "case",
          fmt::format("'{}' is not a case code of thesis Table 3.2 (RX025 ... FF100)", *meta_case));
    if (meta_case && name_case && *meta_case != *name_case)
      throw error(metadata_line_.at("case"), "case",
                  fmt::format("'{}' but the file name says '{}'", *meta_case, *name_case));
    if (!meta_case && !name_case)
      throw error(0, "", "no case code: add '# case: <CODE>' or name the file <CASE>_t<N>.csv");
    trial_.case_code = meta_case ? *meta_case : *name_case;
    identify_trial(name_trial);
  }

  void identify_trial(std::optional<int> name_trial) {
    const auto meta = metadata("trial");
    std::optional<int> meta_trial;
    if (meta) {
      meta_trial = positive_int(*meta);
      if (!meta_trial)
        throw error(metadata_line_.at("trial"), "trial",
                    fmt::format("'{}' is not a positive integer", *meta));
      if (name_trial && *meta_trial != *name_trial)
        throw error(metadata_line_.at("trial"), "trial",
                    fmt::format("{} but the file name says {}", *meta_trial, *name_trial));
    }
    trial_.trial = meta_trial.value_or(name_trial.value_or(0));
  }

  std::optional<std::string> metadata(const std::string& key) const {
    const auto it = trial_.metadata.find(key);
    if (it == trial_.metadata.end()) return std::nullopt;
    return it->second;
  }

  static std::optional<int> positive_int(std::string_view s) {
    int v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || v <= 0) return std::nullopt;
    return v;
  }

  fs::path source_;
  std::vector<Line> lines_;
  MeasuredTrial trial_;
  std::map<std::string, int> metadata_line_;
  double previous_time_ = 0.0;
  int previous_line_ = 0;
  std::vector<double> row_times_;  // of every data row, with its line number
  std::vector<int> row_lines_;
};

}  // namespace

MeasuredTrial parse_trial_csv(std::string_view text, const fs::path& source) {
  return TrialReader(text, source).read();
}

MeasuredTrial read_trial_csv(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw rig_input_error(file, 0, "", "cannot open the file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw rig_input_error(file, 0, "", "reading the file failed");
  return parse_trial_csv(text.str(), file);
}

}  // namespace ccm::rig
