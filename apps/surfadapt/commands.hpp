// SPDX-License-Identifier: BSD-3-Clause
// The commands of the surfadapt tool; each returns the process's exit status (0 done,
// 1 failed, 2 bad usage). argv[1] is the command's name.
#pragma once

int demo_command(int argc, char **argv);
int info_command(int argc, char **argv);
int features_command(int argc, char **argv);
int convert_command(int argc, char **argv);
int remesh_command(int argc, char **argv);
int enright_command(int argc, char **argv);
int vortex_command(int argc, char **argv);
