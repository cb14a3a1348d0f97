// SPDX-License-Identifier: BSD-3-Clause
// Progress of a long command: one line on standard error, rewritten in place, shown only
// when standard error is a terminal, so that logs, pipes and tests stay as they were.
#pragma once

class Progress {
public:
    Progress();
    ~Progress() { clear(); }
    Progress(const Progress &) = delete;
    Progress &operator=(const Progress &) = delete;

    // Replaces the line with the text (printf-style).
    void show(const char *format, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 2, 3)))
#endif
        ;
    // Erases the line, before the command prints something of its own.
    void clear();

private:
    bool on_terminal_;
    bool shown_ = false;
};
