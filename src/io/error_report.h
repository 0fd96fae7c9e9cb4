// report_error: how a command's final error message leaves the process. It goes to stderr, and the
// last one is kept so that a distributed run can pass it to the rank that prints for every rank
// (src/distributed/cluster.h): under mpirun only rank 0's stderr is shown in full. report_warnings:
// how loading warnings leave it.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace rayvec {

// Prints `message` and a newline to stderr and keeps it as last_error_message().
void report_error(const std::string& message);
const std::string& last_error_message();

// The most loading warnings report_warnings prints one by one.
inline constexpr std::size_t kShownWarnings = 20;

// Prints "<label>: <warning>" to stderr for the first kShownWarnings of `warnings`, then one line
// saying how many more there were: a file of a hundred thousand odd lines does not bury the
// terminal (or the one error a user is looking for) under them.
void report_warnings(const std::vector<std::string>& warnings, const char* label = "warning");

}  // namespace rayvec
