// The gmsh library, in process: one session per file read, finalized however
// the reading ends, and gmsh's errors turned into messages that name the
// file. Used for the blank's planform and for the tools' surfaces.
#pragma once

#include <string>

namespace formsolve
{
  namespace app
  {
    class GmshSession
    {
    public:
      /// gmsh quiet (no terminal output); options as gmsh's command line
      /// takes them with -setnumber.
      GmshSession();
      ~GmshSession();
      GmshSession(const GmshSession &)            = delete;
      GmshSession &operator=(const GmshSession &) = delete;

      /// Runs @p f; a gmsh error becomes dealii::ExcMessage("<what>
      /// '<file>': gmsh <doing> failed: <gmsh's last error>").
      template <typename F>
      void checked(const std::string &what,
                   const std::string &file,
                   const std::string &doing,
                   F                &&f) const
      {
        try
          {
            f();
            return;
          }
        catch (...)
          {}
        fail(what, file, doing);
      }

    private:
      [[noreturn]] static void fail(const std::string &what,
                                    const std::string &file,
                                    const std::string &doing);
    };
  } // namespace app
} // namespace formsolve
