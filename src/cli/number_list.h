#pragma once
// Command-line lists of numbers ("640x480", "30,20"), shared by the corbel-cli commands.
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace corbel::cli {

// The finite numbers of `text` separated by `sep`; nullopt if any item is empty or not a number.
inline std::optional<std::vector<double>> numberList(const std::string& text, char sep) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, sep)) {
    char* end = nullptr;
    const double d = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(d)) return std::nullopt;
    out.push_back(d);
  }
  return out;
}

}  // namespace corbel::cli
