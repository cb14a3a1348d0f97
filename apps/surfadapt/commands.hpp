// SPDX-License-Identifier: BSD-3-Clause
// The commands of the surfadapt tool; each returns the process's exit status (0 done,
// 1 failed, 2 bad usage). argv[1] is the command's name.
#pragma once

int demo_command(int argc, char **argv);
int info_command(int argc, char **argv);
int features_command(int argc, char **argv);
int convert_command(int argc, char **argv);
int remesh_command(int argc, char **argv);
int repair_command(int argc, char **argv);

// Prints to standard error what `surfadapt repair` would change in the file, if anything
// (for a mesh the library refused).
void suggest_repair(const char *path);
int enright_command(int argc, char **argv);
int vortex_command(int argc, char **argv);
