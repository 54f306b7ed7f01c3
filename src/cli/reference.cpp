// corbel_cli_reference: docs/cli.md, written from the CLI11 declarations of corbel (the editor)
// and corbel-cli, so the reference says what the programs parse.
//   corbel_cli_reference            the Markdown on stdout
//   corbel_cli_reference --check F  exit 1 when F differs from it (the test cli_reference_current)
#include "cli/commands.h"
#include "editor/options.h"

#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace {

const char* const kIntro = R"(# Command-line reference

<!-- Generated from src/cli/commands.cpp and src/editor/options.cpp by corbel_cli_reference:
     edit those, then run scripts/cli-reference (the test cli_reference_current fails until then). -->

corbel comes as two programs. `corbel` is the editor: a window with the model, its panels and an
undo history, which can also be driven from the command line for scripted runs and screenshots.
`corbel-cli` runs the same kernels without a window, one subcommand each: it renders, exports and
checks projects, extrudes footprints, analyses and simulates masonry, draws KIFS buildings, grows
housing and builds towns. [The user guide](user-guide.md) shows them at work; this page lists
every option.

Every command and subcommand takes `--help` (its usage, on stdout) and `--version`. Exit codes:
0 success, 1 bad input (a missing or malformed file, a kernel's failure, a failed check), 2 a bad
command line (an unknown option, a missing or malformed value, options that exclude each other).
A value may start with a minus sign (`--tilt -10`, `--camera -60,30`). An option that may repeat
takes one value each time (`--set a=1 --set b=2`); any other option given twice keeps the last.
)";

// `text` for a Markdown table cell: pipes escaped, line breaks as spaces.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

std::string code(const std::string& text) { return text.empty() ? "" : "`" + cell(text) + "`"; }

std::string commandPath(const CLI::App& command) {
  std::string path = command.get_name();
  for (const CLI::App* c = command.get_parent(); c; c = c->get_parent()) path = c->get_name() + " " + path;
  return path;
}

// What an option's validators allow ("sides 1..8192"), "" when it has none.
std::string allowedOf(CLI::Option* o) {
  try {
    return o->get_validator()->get_description();
  } catch (const CLI::OptionNotFound&) {
    return "";
  }
}

// An option's value as declared ("WxH"): its type name without what the validators allow.
std::string valueOf(CLI::Option* o) {
  const std::string t = o->get_type_name(), allowed = allowedOf(o);
  return allowed.empty() ? t : t.substr(0, t.size() - allowed.size() - 1);
}

bool builtIn(const CLI::Option* o) {
  const std::string name = o->get_name();
  return name == "--help" || name == "--version";
}

// The usage lines: the command's own arguments, and its subcommands when it has some.
std::string usageLines(CLI::App& command) {
  std::string line = commandPath(command);
  bool own = false, optional = false;
  for (CLI::Option* o : command.get_options()) {
    if (builtIn(o)) continue;
    own = true;
    if (o->get_positional())
      line += o->get_required() ? " " + o->get_name() : " [" + o->get_name() + "]";
    else if (o->get_required())
      line += " " + o->get_name() + " " + valueOf(o);
    else
      optional = true;
  }
  if (optional) line += " [OPTIONS]";
  const bool subcommands = !command.get_subcommands([](const CLI::App*) { return true; }).empty();
  const std::string sub = commandPath(command) + " SUBCOMMAND [OPTIONS]";
  return own ? line + (subcommands ? "\n" + sub : "") : sub;
}

// What an option's description leaves out and the declaration says: required, needs, excludes.
std::string constraints(const CLI::Option* o) {
  std::string out;
  if (o->get_required()) out += " Required.";
  for (const CLI::Option* n : o->get_needs()) out += " Needs " + n->get_name() + ".";
  for (const CLI::Option* x : o->get_excludes()) out += " Not with " + x->get_name() + ".";
  return out;
}

void section(std::ostream& out, CLI::App& command, int level) {
  out << "\n" << std::string(std::size_t(level), '#') << " " << commandPath(command) << "\n\n";
  out << command.get_description() << "\n\n";
  out << "```\n" << usageLines(command) << "\n```\n\n";
  const std::vector<CLI::App*> subcommands = command.get_subcommands([](CLI::App*) { return true; });
  if (!subcommands.empty()) {
    out << "Subcommands:";
    for (std::size_t i = 0; i < subcommands.size(); ++i)
      out << (i ? ", " : " ") << "`" << subcommands[i]->get_name() << "`";
    out << ".\n\n";
  }
  bool header = false;
  for (CLI::Option* o : command.get_options()) {
    if (builtIn(o)) continue;
    if (!header) {
      out << "| argument | value | allowed | default | what it does |\n| --- | --- | --- | --- | --- |\n";
      header = true;
    }
    out << "| " << code(o->get_name()) << " | " << code(valueOf(o)) << " | " << cell(allowedOf(o)) << " | "
        << code(o->get_default_str())
        << " | " << cell(o->get_description() + constraints(o)) << " |\n";
  }
  const std::string footer = command.get_footer();
  if (!footer.empty()) out << (header ? "\n" : "") << footer << "\n";
  for (CLI::App* sub : subcommands) section(out, *sub, level + 1);
}

std::string reference() {
  std::ostringstream out;
  out << kIntro;
  {
    CLI::App editor;
    corbel::editor::EditorOptions options;
    corbel::editor::declareEditorOptions(editor, options);
    section(out, editor, 2);
  }
  CLI::App cli;
  corbel::cli::Requests requests;
  corbel::cli::declareCommands(cli, requests);
  section(out, cli, 2);
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string text = reference();
  if (argc == 3 && !std::strcmp(argv[1], "--check")) {
    std::ifstream in(argv[2], std::ios::binary);
    std::stringstream committed;
    committed << in.rdbuf();
    if (committed.str() == text) return 0;
    std::cerr << argv[2] << " is stale: run scripts/cli-reference\n";
    return 1;
  }
  if (argc != 1) {
    std::cerr << "usage: corbel_cli_reference [--check docs/cli.md]\n";
    return 2;
  }
  std::cout << text;
  return 0;
}
