#include "app/validate_record.hpp"

#include <fmt/format.h>

#include "app/data_paths.hpp"
#include "app/output_file.hpp"
#include "app/validate_output.hpp"
#include "bench_test/units.hpp"
#include "db/store/study_store.hpp"
#include "db/store/validation_store.hpp"
#include "reports/figures/report_content.hpp"
#include "reports/figures/validation_section.hpp"
#include "reports/tables/table.hpp"

namespace ccm {
namespace {

// A rated score (the store's rating table holds those; validation.json holds every score).
db::ValidationScoreRow score_row(const std::string& channel, const bench::ChannelScore& s,
                                 bool left_out) {
  const correlate::CurveRating& r = *s.rating;
  return {channel,          s.against,
          left_out,         static_cast<long long>(s.samples),
          s.nrmse,          s.peak_measured,
          s.peak_simulated, s.peak_time_error,
          r.corridor,       r.phase,
          r.magnitude,      r.slope,
          r.overall,        std::string(correlate::grade_name(r.grade))};
}

}  // namespace

std::filesystem::path validation_store(const ValidateArgs& args) {
  const std::filesystem::path store =
      args.db.empty() ? std::filesystem::path(kMainJobStore) : args.db;
  if (std::filesystem::exists(store)) db::StudyStore check(store, db::Access::read_only);
  return store;
}

db::ValidationRow validation_row(const ValidateArgs& args, const BenchData& data,
                                 const bench::BenchScores& scores,
                                 const std::set<std::string>& left_out,
                                 const nlohmann::json& document) {
  db::ValidationRow row;
  row.scene = args.scene.string();
  row.data = args.data.string();
  if (document.contains("fit")) row.fitted = document["fit"]["parameters"].dump();
  row.document = document.dump();
  for (const bench::ChannelResult& c : scores.channels) {
    for (const bench::ChannelScore& s : c.trials)
      if (s.rating) row.scores.push_back(score_row(c.channel, s, left_out.count(s.against) > 0));
    if (c.mean && c.mean->rating) row.scores.push_back(score_row(c.channel, *c.mean, false));
    row.curves.push_back({c.channel,
                          std::string(bench::si_unit(data.mapping.channel(c.channel)->unit)),
                          channel_curves_csv(c.curves)});
  }
  return row;
}

std::string record_validation_row(const std::filesystem::path& store,
                                  const db::ValidationRow& row) {
  if (!std::filesystem::is_regular_file(store))
    return fmt::format("not recorded: no store at {}", store.string());
  const long long id = db::record_validation(store, row);
  return fmt::format("recorded in {} (validation {}; `ccm report` shows it)", store.string(), id);
}

void write_validation_figures(const std::filesystem::path& out, const db::ValidationRow& row) {
  reports::ReportContent content;
  content.sections.push_back(reports::validation_section({row}));
  reports::render_figures(content);
  const reports::Section& s = content.sections.front();
  for (const reports::Table& t : s.tables) write_atomic(out / "ratings.csv", reports::to_csv(t));
  for (const reports::Figure& f : s.figures) {
    // fig-validation-1-<channel> in the report; <channel>.svg here, beside <channel>.csv.
    const std::string prefix = "fig-validation-1-";
    write_atomic(out / (f.id.substr(prefix.size()) + ".svg"), f.svg);
  }
}

}  // namespace ccm
