// `ccm` with a word that is no command: the word named, and the nearest command suggested,
// before CLI11 parses (CLI11 alone says "A subcommand is required", or takes a later word for
// the command: `ccm stduy run` ran `ccm run`).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace ccm {

// Walks the leading words of the command line down the subcommand tree of `app`; at the first
// word that is not a subcommand where one is expected, returns
// "unknown command 'study sttus' (did you mean 'study status'?); the commands of 'ccm study'
// are: run, status, scene". Empty when the words name commands (or an option comes first).
// The suggestion is config/did_you_mean.hpp's closest name (at most 2 edits away).
std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv);

}  // namespace ccm
