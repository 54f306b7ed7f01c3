#pragma once
// The run function of each corbel-cli subcommand: it reads the request the parse filled
// (cli/commands.h), does the semantic checks CLI11 cannot (throwing UsageError, exit 2), runs
// the kernel and returns the exit code; other faults are thrown as corbel::Error (exit 1).
#include "cli/commands.h"

namespace corbel::cli {

int run(const RenderRequest& r);    // scene_commands.cpp
int run(const ExportRequest& r);    // scene_commands.cpp
int run(const CheckRequest& r);     // scene_commands.cpp
int run(const EditRequest& r);      // edit_command.cpp
int run(const ExtrudeRequest& r);   // extrude_command.cpp
int run(const StaticsArchRequest& r);     // statics_cli.cpp
int run(const StaticsExampleRequest& r);  // statics_cli.cpp
int run(const StaticsProjectRequest& r);  // statics_cli.cpp
int run(const SimulateRequest& r);  // simulate_cli.cpp
int run(const KifsRequest& r);      // kifs_command.cpp
int run(const GrowRequest& r);      // grow.cpp
int run(const CompleteRequest& r);  // complete.cpp
int run(const CityRequest& r);      // city_command.cpp
int run(const CitySplitRequest& r);  // city_split_command.cpp
int run(const CityMergeRequest& r);  // city_split_command.cpp

}  // namespace corbel::cli
