// SPDX-License-Identifier: BSD-3-Clause
#include "progress.hpp"

#include <cstdarg>
#include <cstdio>
#include <unistd.h>

Progress::Progress() : on_terminal_(isatty(STDERR_FILENO) == 1) {}

void Progress::show(const char *format, ...)
{
    if (!on_terminal_)
        return;
    std::fflush(stdout); // what the command printed comes first
    std::fputs("\r", stderr);
    va_list args;
    va_start(args, format);
    std::vfprintf(stderr, format, args);
    va_end(args);
    std::fputs("\033[K", stderr); // erase the rest of a longer previous line
    std::fflush(stderr);
    shown_ = true;
}

void Progress::clear()
{
    if (!shown_)
        return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    shown_ = false;
}
