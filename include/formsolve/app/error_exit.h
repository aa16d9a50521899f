// Ends the program after an exception on any rank: one message, printed
// once, and a non-zero exit on every rank, never a hang.
#pragma once

#include <mpi.h>

#include <exception>
#include <string>

namespace formsolve
{
  namespace app
  {
    /// Call once after MPI_Init, on every rank: reserves a communicator for
    /// error handling, so that it never mixes with the work's collectives.
    void prepare_error_exit();

    /// To be called from the catch block of main with the one-line message.
    /// If every rank reaches it within @p wait_seconds (the same error
    /// everywhere, e.g. bad input), rank 0 prints "formsolve: error: ..." and
    /// all ranks return 1. Otherwise the failing rank prints its message,
    /// prefixed with its rank if not 0, and aborts the job (exit status 1).
    int error_exit(const std::string &message, const double wait_seconds = 5);

    /// The message of an exception on one line (deal.II's are spread over
    /// several indented lines).
    std::string one_line(const std::string &text);

    /// What an exception says, on one line: deal.II's own text without its
    /// file, line and stack (print_info), else what().
    std::string exception_text(const std::exception &e);

    /// Test hook: if the environment variable FORMSOLVE_FAIL_ON_RANK names
    /// this rank and FORMSOLVE_FAIL_AT_STEP this step, throw there, as a
    /// failing file write on one rank would (tests/cases/check_rank_error.sh).
    void injected_failure(const unsigned int step);

    /// Test hook: if FORMSOLVE_KILL_AT is "<point>:<step>" (point "step":
    /// before the step is solved, "checkpoint": half-way through writing the
    /// checkpoint of that step), this process kills itself with SIGKILL
    /// there, as a power cut or the batch system would
    /// (tests/cases/check_resume.sh).
    void injected_kill(const std::string &point, const unsigned int step);
  } // namespace app
} // namespace formsolve
