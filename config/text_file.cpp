#include "config/text_file.hpp"

#include <fstream>
#include <sstream>

#include "config/config_error.hpp"

namespace ccm {

namespace fs = std::filesystem;

std::string read_config_text(const std::filesystem::path& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) throw config_error(file, 0, "", "no such file");
  if (fs::is_directory(file, ec)) throw config_error(file, 0, "", "is a directory, not a file");
  std::ifstream in(file, std::ios::binary);
  if (!in.is_open()) throw config_error(file, 0, "", "cannot be opened for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw config_error(file, 0, "", "cannot be read");
  return text.str();
}

}  // namespace ccm
