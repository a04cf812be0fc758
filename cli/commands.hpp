// cli/commands.hpp — the subcommands of the `shitsukan` tool (cli/main.cpp dispatches).
// Each takes the arguments after its name and returns the exit code: 0 done, 1 a library
// error (the Status message), 2 a bad flag or value (one line naming the flag and range).
#pragma once

namespace shitsukan::cli {

int run_solid(int argc, char** argv, bool wood);  // marble, wood
int run_leather(int argc, char** argv);
int run_wrinkly(int argc, char** argv);
int run_bark(int argc, char** argv);
int run_ist(int argc, char** argv);
int run_normals(int argc, char** argv);

}  // namespace shitsukan::cli
