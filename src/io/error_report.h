// report_error: how a command's final error message leaves the process. It goes to stderr, and the
// last one is kept so that a distributed run can pass it to the rank that prints for every rank
// (src/distributed/cluster.h): under mpirun only rank 0's stderr is shown in full.
#pragma once
#include <string>

namespace rayvec {

// Prints `message` and a newline to stderr and keeps it as last_error_message().
void report_error(const std::string& message);
const std::string& last_error_message();

}  // namespace rayvec
