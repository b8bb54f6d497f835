// Paths into a scene file's TOML document, as a grid over a scene names its axes
// (docs/grid-file.md, "Grids over your own scene"): keys joined by dots, an array element by its
// index ("contact.pairs[0].friction", "bodies.shell.initial_velocity[2]") or, in an array of
// tables whose entries have a `name`, by that name ("bodies.shell.material.E"). A path to a vector
// (an array of numbers) stands for its magnitude: "bodies.shell.initial_velocity" = 3 is a speed of
// 3 m/s in the template's direction (a negative value reverses it).
#pragma once

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ccm {

// The number at `path` (a vector's magnitude), or nullopt when the path leads to neither.
std::optional<double> number_at_path(const toml::table& doc, std::string_view path);

// Every path of the document that leads to a number or a vector, in document order (bodies by
// name; a vector before its components).
std::vector<std::string> number_paths(const toml::table& doc);

// Sets the number at `path` (which must lead to a number: number_at_path). An integer stays an
// integer when `value` is integral. A vector is scaled to the magnitude `value`, its direction
// kept (refused for a zero vector: it has none).
void set_number_at_path(toml::table& doc, std::string_view path, double value);

// The document as TOML text (as toml++ writes it), for the scene reader.
std::string document_text(const toml::table& doc);

// Why `path` leads to no number of the document: the nearest path that does, or those that
// share its longest valid beginning.
std::string path_problem(const toml::table& doc, std::string_view path);

}  // namespace ccm
