#include "core/command_line.h"

#include "core/project_io.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <utility>

namespace corbel {
namespace {

std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

std::optional<double> finiteNumber(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<long long> wholeNumber(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE) return std::nullopt;
  return v;
}

std::optional<std::pair<int, int>> sizeOf(const std::string& text, int lo, int hi) {
  const auto x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  const auto w = wholeNumber(text.substr(0, x)), h = wholeNumber(text.substr(x + 1));
  if (!w || !h || *w < lo || *h < lo || *w > hi || *h > hi) return std::nullopt;
  return std::make_pair(int(*w), int(*h));
}

// "a, b or c".
std::string listed(const std::vector<std::string>& words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i)
    out += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return out;
}

// "statics arch" for that subcommand, "" for the program itself.
std::string commandPath(const CLI::App& command) {
  std::string path;
  for (const CLI::App* c = &command; c->get_parent(); c = c->get_parent())
    path = c->get_name() + (path.empty() ? "" : " " + path);
  return path;
}

}  // namespace

std::string versionText(const std::string& program) {
  return program + " " + CORBEL_VERSION + " (project format " + std::to_string(kProjectVersion) + ")";
}

void addVersionFlag(CLI::App& command, const std::string& program) {
  command.set_version_flag("--version", versionText(program), "Print the version and exit");
}

CLI::Option* addSize(CLI::App& command, const std::string& name, Size& size, int lo, int hi,
                     const std::string& description) {
  const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
  CLI::Option* o = command.add_option_function<std::string>(
      name,
      [&size, lo, hi](const std::string& text) {
        const auto wh = sizeOf(text, lo, hi);  // checked before, by the validator
        size.width = wh->first;
        size.height = wh->second;
        size.given = true;
      },
      description);
  o->check(CLI::Validator(
      [lo, hi, range](const std::string& text) {
        return sizeOf(text, lo, hi) ? std::string()
                                    : "expected WxH with whole numbers in " + range + ", like 800x600, not '" + text + "'";
      },
      "sides " + range));
  o->type_name("WxH");
  o->default_str(std::to_string(size.width) + "x" + std::to_string(size.height));
  return o;
}

CLI::Validator numberIn(double lo, double hi) {
  const std::string range = "[" + shortNumber(lo) + ", " + shortNumber(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](const std::string& text) {
        const auto v = finiteNumber(text);
        return v && *v >= lo && *v <= hi ? std::string() : "expected a number in " + range + ", not '" + text + "'";
      },
      range);
}

CLI::Validator wholeIn(long long lo, long long hi) {
  const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](const std::string& text) {
        const auto v = wholeNumber(text);
        return v && *v >= lo && *v <= hi ? std::string() : "expected a whole number in " + range + ", not '" + text + "'";
      },
      range);
}

CLI::Validator oneOf(const std::vector<std::string>& words, const std::vector<std::string>& hidden) {
  return CLI::Validator(
      [words, hidden](const std::string& text) {
        for (const auto* list : {&words, &hidden})
          for (const std::string& w : *list)
            if (w == text) return std::string();
        return "expected " + listed(words) + ", not '" + text + "'";
      },
      "");
}

std::string choices(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : "|") + w;
  return out;
}

CLI::Option* addRepeated(CLI::App& command, const std::string& name, std::vector<std::string>& values,
                         const std::string& description) {
  return command.add_option(name, values, description + " May repeat.")
      ->expected(1)
      ->allow_extra_args(false)
      ->take_all();
}

const CLI::App& chosenCommand(const CLI::App& app) {
  const CLI::App* at = &app;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  return *at;
}

int parseCommandLine(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
    return -1;
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();  // the chosen subcommand's help
    return 0;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {  // any other way CLI11 says "done"
      std::cout << app.help();
      return 0;
    }
    const CLI::App& at = chosenCommand(app);
    std::string message = e.what();
    // Arguments no declaration takes come first: CLI11 checks required options before them,
    // and a misspelt option is often why a required one is missing.
    const std::vector<std::string> extra = at.remaining();
    if (!extra.empty()) {
      if (&at == &app && !app.get_subcommands([](const CLI::App*) { return true; }).empty())
        message = "unknown command '" + extra.front() + "'";
      else if (extra.front().rfind("-", 0) == 0)
        message = "unknown option " + extra.front();
      else
        message = "unexpected argument '" + extra.front() + "'";
    }
    const std::string path = commandPath(at);
    std::cerr << app.get_name() << ": " << (path.empty() ? "" : path + ": ") << message << "\n"
              << "(see '" << app.get_name() << (path.empty() ? "" : " " + path) << " --help')\n";
    return 2;
  }
}

}  // namespace corbel
