#include <deal.II/base/exceptions.h>

#include <formsolve/app/error_exit.h>

#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <thread>

namespace formsolve
{
  namespace app
  {
    namespace
    {
      MPI_Comm error_comm = MPI_COMM_NULL;
    }

    void prepare_error_exit()
    {
      MPI_Comm_dup(MPI_COMM_WORLD, &error_comm);
    }

    namespace
    {
      /// Length of the valid UTF-8 sequence at @p i, 0 if there is none.
      std::size_t utf8_length(const std::string &s, const std::size_t i)
      {
        const auto        c = static_cast<unsigned char>(s[i]);
        const std::size_t n = (c >= 0xf0 && c < 0xf5)   ? 4
                              : (c >= 0xe0 && c < 0xf0) ? 3
                              : (c >= 0xc2 && c < 0xe0) ? 2
                                                        : 0;
        if (n == 0 || i + n > s.size())
          return 0;
        for (std::size_t k = 1; k < n; ++k)
          if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80)
            return 0;
        // No overlong forms, surrogates or code points beyond U+10FFFF.
        const auto d = static_cast<unsigned char>(s[i + 1]);
        if ((c == 0xe0 && d < 0xa0) || (c == 0xed && d > 0x9f) ||
            (c == 0xf0 && d < 0x90) || (c == 0xf4 && d > 0x8f))
          return 0;
        return n;
      }
    } // namespace

    std::string one_line(const std::string &text)
    {
      // Input echoed in a message (a garbage line of a .prm) must not break
      // the one line or the terminal: control characters and bytes that are
      // not UTF-8 become '?', and very long messages are cut.
      std::string clean;
      for (std::size_t i = 0; i < text.size();)
        {
          const auto c = static_cast<unsigned char>(text[i]);
          if (c < 0x80)
            {
              clean += std::isspace(c)           ? ' '
                       : (c < 0x20 || c == 0x7f) ? '?'
                                                 : text[i];
              ++i;
            }
          else if (const auto n = utf8_length(text, i); n > 0)
            {
              const auto code =
                n == 2 ? ((c & 0x1f) << 6) | (text[i + 1] & 0x3f) : 0x100;
              // C1 controls (U+0080..U+009F) and NEL break lines too.
              clean += code < 0xa0 ? std::string("?") : text.substr(i, n);
              i += n;
            }
          else
            {
              clean += '?';
              ++i;
            }
        }
      std::istringstream words(clean);
      std::string        line, word;
      while (words >> word)
        line += (line.empty() ? "" : " ") + word;
      constexpr std::size_t max_length = 2000;
      if (line.size() > max_length)
        {
          std::size_t cut = max_length;
          while (cut > 0 &&
                 (static_cast<unsigned char>(line[cut]) & 0xc0) == 0x80)
            --cut;
          line = line.substr(0, cut) + " ... (message cut)";
        }
      return line;
    }

    std::string exception_text(const std::exception &e)
    {
      std::ostringstream s;
      if (const auto *d = dynamic_cast<const dealii::ExceptionBase *>(&e))
        d->print_info(s);
      else
        s << e.what();
      return one_line(s.str());
    }

    int error_exit(const std::string &message, const double wait_seconds)
    {
      int rank = 0, size = 1;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      MPI_Comm_size(MPI_COMM_WORLD, &size);
      bool everyone = size == 1;
      if (!everyone && error_comm != MPI_COMM_NULL)
        {
          MPI_Request request;
          MPI_Ibarrier(error_comm, &request);
          const auto end = std::chrono::steady_clock::now() +
                           std::chrono::duration<double>(wait_seconds);
          int done = 0;
          while (!done && std::chrono::steady_clock::now() < end)
            {
              MPI_Test(&request, &done, MPI_STATUS_IGNORE);
              if (!done)
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            }
          everyone = done != 0;
        }
      if (everyone)
        {
          if (rank == 0)
            std::cerr << "formsolve: error: " << message << std::endl;
          return 1;
        }
      // Only some ranks failed; the others wait in a collective for ever.
      std::cerr << "formsolve: error"
                << (rank != 0 ? " (rank " + std::to_string(rank) + ")" : "")
                << ": " << message << std::endl;
      MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }

    void injected_failure(const unsigned int step)
    {
      const char *r = std::getenv("FORMSOLVE_FAIL_ON_RANK");
      const char *s = std::getenv("FORMSOLVE_FAIL_AT_STEP");
      if (r == nullptr || s == nullptr)
        return;
      int rank = 0;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      AssertThrow(rank != std::atoi(r) || step != unsigned(std::atoi(s)),
                  dealii::ExcMessage(
                    "injected failure (FORMSOLVE_FAIL_ON_RANK=" +
                    std::string(r) + ", FORMSOLVE_FAIL_AT_STEP=" + s + ")"));
    }

    void injected_kill(const std::string &point, const unsigned int step)
    {
      const char *k = std::getenv("FORMSOLVE_KILL_AT");
      if (k != nullptr && std::string(k) == point + ":" + std::to_string(step))
        std::raise(SIGKILL);
    }
  } // namespace app
} // namespace formsolve
