#include "app/command_words.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "config/did_you_mean.hpp"

namespace ccm {
namespace {

std::vector<const CLI::App*> subcommands_of(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App*) { return true; });
}

}  // namespace

std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv) {
  const CLI::App* level = &app;
  std::string path;  // the commands walked so far, e.g. "study "
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    const auto commands = subcommands_of(*level);
    if (commands.empty() || word.starts_with('-')) return std::nullopt;
    const auto match = std::find_if(commands.begin(), commands.end(),
                                    [&](const CLI::App* c) { return c->check_name(word); });
    if (match != commands.end()) {
      level = *match;
      path += word + " ";
      continue;
    }
    std::vector<std::string> names;
    for (const CLI::App* c : commands) names.push_back(c->get_name());
    const std::vector<std::string_view> allowed(names.begin(), names.end());
    const std::string suggestion(closest_name(word, allowed));
    const std::string parent = fmt::format("{} {}", app.get_name(), path);
    return fmt::format(
        "unknown command '{}{}'{}; the commands of '{}' are: {}", path, word,
        suggestion.empty() ? "" : fmt::format(" (did you mean '{}{}'?)", path, suggestion),
        parent.substr(0, parent.size() - 1), fmt::join(names, ", "));
  }
  return std::nullopt;
}

}  // namespace ccm
