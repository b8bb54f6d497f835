// Paths into a scene file's TOML document, as a grid over a scene names its axes
// (docs/grid-file.md, "Grids over your own scene"): keys joined by dots, an array element by its
// index ("contact.pairs[0].friction", "bodies.shell.initial_velocity[2]") or, in an array of
// tables whose entries have a `name`, by that name ("bodies.shell.material.E").
#pragma once

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ccm {

// The number at `path`, or nullopt when the path does not lead to a number.
std::optional<double> number_at_path(const toml::table& doc, std::string_view path);

// Every path of the document that leads to a number, in document order (bodies by name).
std::vector<std::string> number_paths(const toml::table& doc);

// Sets the number at `path` (which must lead to a number: number_at_path). An integer stays an
// integer when `value` is integral.
void set_number_at_path(toml::table& doc, std::string_view path, double value);

// Why `path` leads to no number of the document: the nearest path that does, or those that
// share its longest valid beginning.
std::string path_problem(const toml::table& doc, std::string_view path);

}  // namespace ccm
