// corbel-cli: the headless tools of corbel. Thin: the command line is declared in
// cli/commands.h, parsed by CLI11, and the chosen subcommand's run function (cli/run.h) is called
// with its request.
#include "cli/commands.h"
#include "cli/guarded.h"
#include "cli/run.h"
#include "core/command_line.h"

#include <iostream>
#include <variant>

int main(int argc, char** argv) {
  CLI::App app;
  corbel::cli::Requests requests;
  corbel::cli::declareCommands(app, requests);
  if (argc < 2) {
    std::cout << app.help();
    return 2;
  }
  if (const int code = corbel::parseCommandLine(app, argc, argv); code >= 0) return code;
  const corbel::cli::Request* request = requests.chosen(app);
  if (!request) {  // options of the program alone, no subcommand
    std::cerr << "corbel-cli: expected a subcommand\n" << app.help();
    return 2;
  }
  return corbel::cli::guarded([&] { return std::visit([](const auto& r) { return corbel::cli::run(r); }, *request); });
}
