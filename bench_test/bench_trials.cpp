#include "bench_test/bench_trials.hpp"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>
#include <optional>

#include "config/config_error.hpp"
#include "config/did_you_mean.hpp"
#include "config/text_file.hpp"
#include "rig_models/measurement/clock_jump.hpp"
#include "rig_models/measurement/csv_cells.hpp"

namespace ccm::bench {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMinRows = 10;

struct Lines {
  std::vector<std::string_view> text;
  std::vector<int> number;  // 1-based line numbers of the non-blank lines
};

// The non-blank lines that are not comments, a UTF-8 byte-order mark and CR line ends dropped.
Lines lines_of(std::string_view text, std::string_view comment) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  Lines out;
  int number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string_view::npos) continue;
    if (!comment.empty() && line.substr(start).starts_with(comment)) continue;
    out.text.push_back(line);
    out.number.push_back(number);
  }
  return out;
}

// The index of `name` in the header, refused when missing (with the nearest header name).
std::size_t column_index(const std::vector<std::string_view>& header, const std::string& name,
                         const fs::path& source, int line) {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) {
    const std::string_view near = closest_name(name, header);
    throw config_error(source, line, name,
                       near.empty() ? std::string("the mapping names this column; the header "
                                                  "lacks it")
                                    : fmt::format("the mapping names this column; the header "
                                                  "lacks it (did you mean '{}'?)",
                                                  near));
  }
  return static_cast<std::size_t>(it - header.begin());
}

// A cell without one pair of surrounding double quotes ("Force [kN]" as many loggers write it).
std::string_view unquoted(std::string_view cell) {
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"')
    return cell.substr(1, cell.size() - 2);
  return cell;
}

std::vector<std::string_view> cells_of(std::string_view line, char delimiter) {
  std::vector<std::string_view> cells = rig::split_cells(line, delimiter);
  for (std::string_view& c : cells) c = unquoted(c);
  return cells;
}

std::string delimiter_name(char d) { return d == '\t' ? std::string("tab") : std::string(1, d); }

// The index (into lines) of the header: the mapping's header_line, or the first line.
std::size_t header_index(const Lines& lines, const fs::path& source, const BenchMapping& m) {
  if (lines.text.empty()) throw config_error(source, 0, "", "the file is empty");
  if (m.header_line == 0) return 0;
  for (std::size_t i = 0; i < lines.number.size(); ++i)
    if (lines.number[i] == m.header_line) return i;
  throw config_error(source, m.header_line, "",
                     fmt::format("the mapping's header_line {} is blank or past the end of the "
                                 "file",
                                 m.header_line));
}

std::vector<std::string_view> read_header(std::string_view line, int number, const fs::path& source,
                                          const BenchMapping& m) {
  std::vector<std::string_view> header = cells_of(line, m.delimiter);
  if (header.size() == 1)
    for (char d : {',', ';', '\t', '|'})
      if (d != m.delimiter && header[0].find(d) != std::string_view::npos)
        throw config_error(
            source, number, "",
            fmt::format("cells are separated by '{}'; the mapping reads '{}' (set "
                        "delimiter = \"{}\" in [trials])",
                        delimiter_name(d), delimiter_name(m.delimiter), delimiter_name(d)));
  for (std::size_t i = 0; i < header.size(); ++i)
    for (std::size_t j = i + 1; j < header.size(); ++j)
      if (header[i] == header[j] && !header[i].empty())
        throw config_error(source, number, header[i], "the header names this column twice");
  return header;
}

}  // namespace

BenchTrial parse_bench_trial(std::string_view text, const fs::path& source, const BenchMapping& m) {
  const Lines lines = lines_of(text, m.comment);
  const std::size_t h = header_index(lines, source, m);
  const int header_line = lines.number[h];
  const std::vector<std::string_view> header = read_header(lines.text[h], header_line, source, m);
  const bool timed = !m.time_column.empty();
  const std::size_t time_index =
      timed ? column_index(header, m.time_column, source, header_line) : 0;
  std::vector<std::size_t> index;
  for (const ChannelSpec& c : m.channels)
    index.push_back(column_index(header, c.column, source, header_line));
  BenchTrial trial;
  trial.file = source;
  std::vector<rig::TimeSeries> series(m.channels.size());
  std::string decimal_point;  // a cell with its decimal comma made a point
  auto cell = [&](const std::vector<std::string_view>& cells, std::size_t i, int line) {
    std::string_view text_cell = cells[i];
    if (m.decimal == ',') {
      decimal_point.assign(text_cell);
      std::replace(decimal_point.begin(), decimal_point.end(), ',', '.');
      text_cell = decimal_point;
    }
    const rig::CellNumber n = rig::parse_number_cell(text_cell);
    if (!n.problem.empty()) throw config_error(source, line, header[i], n.problem);
    return n.value;
  };
  const std::size_t first = h + 1 + static_cast<std::size_t>(m.skip_after_header);
  for (std::size_t r = first; r < lines.text.size(); ++r) {
    const int line = lines.number[r];
    const std::vector<std::string_view> cells = cells_of(lines.text[r], m.delimiter);
    if (cells.size() != header.size())
      throw config_error(source, line, "",
                         fmt::format("{} cells; the header has {}", cells.size(), header.size()));
    const double t = timed ? cell(cells, time_index, line) * m.time_factor
                           : static_cast<double>(trial.t.size()) / m.sample_rate;
    if (!trial.t.empty() && !(t > trial.t.back()))
      throw config_error(
          source, line, m.time_column,
          fmt::format("time {:.9g} s {} the previous row's {:.9g} s", t,
                      t == trial.t.back() ? "repeats" : "goes back from", trial.t.back()));
    trial.t.push_back(t);
    for (std::size_t c = 0; c < m.channels.size(); ++c) {
      if (m.sparse && cells[index[c]].empty()) continue;  // that sensor did not sample here
      series[c].t.push_back(t);
      series[c].value.push_back(cell(cells, index[c], line) * m.channels[c].si_factor);
    }
  }
  if (trial.t.size() < kMinRows)
    throw config_error(
        source, 0, "",
        fmt::format("{} data rows; a trial needs at least {}", trial.t.size(), kMinRows));
  if (const std::optional<rig::ClockJump> jump = rig::find_clock_jump(trial.t))
    throw config_error(source, lines.number[first + jump->row], m.time_column,
                       fmt::format("the clock jumps {:.6g} s forward, {:.0f} times the median "
                                   "step {:.6g} s",
                                   jump->step, jump->step / jump->median_step, jump->median_step));
  for (std::size_t c = 0; c < m.channels.size(); ++c) {
    if (series[c].t.size() < kMinRows)
      throw config_error(
          source, 0, m.channels[c].column,
          fmt::format("{} samples; a channel needs at least {}", series[c].t.size(), kMinRows));
    trial.channels[m.channels[c].name] = std::move(series[c]);
  }
  return trial;
}

std::vector<BenchTrial> read_bench_trials(const BenchMapping& m) {
  const fs::path folder = m.file.parent_path().empty() ? fs::path(".") : m.file.parent_path();
  std::vector<fs::path> files;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec))
    if (e.is_regular_file() &&
        fnmatch(m.files_pattern.c_str(), e.path().filename().c_str(), 0) == 0)
      files.push_back(e.path());
  if (ec)
    throw config_error(folder, 0, "", fmt::format("cannot list the folder: {}", ec.message()));
  std::sort(files.begin(), files.end());
  if (files.empty())
    throw config_error(m.file, 0, "trials.files",
                       fmt::format("no file in {} matches '{}'", folder.string(), m.files_pattern));
  if (!m.align.offsets.empty() && m.align.offsets.size() != files.size())
    throw config_error(m.file, m.align.line, "align.offsets",
                       fmt::format("{} offsets for {} trials (one per trial, in file-name order)",
                                   m.align.offsets.size(), files.size()));
  std::vector<BenchTrial> trials;
  for (const fs::path& f : files) trials.push_back(parse_bench_trial(read_config_text(f), f, m));
  return trials;
}

}  // namespace ccm::bench
