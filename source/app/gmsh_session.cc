#include <deal.II/base/exceptions.h>

#include <formsolve/app/gmsh_session.h>

#include <gmsh.h>

namespace formsolve
{
  namespace app
  {
    GmshSession::GmshSession()
    {
      gmsh::initialize(0, nullptr, false);
      gmsh::option::setNumber("General.Terminal", 0);
    }

    GmshSession::~GmshSession()
    {
      gmsh::finalize();
    }

    void GmshSession::fail(const std::string &what,
                           const std::string &file,
                           const std::string &doing)
    {
      std::string error;
      gmsh::logger::getLastError(error);
      throw dealii::ExcMessage(what + " '" + file + "': gmsh " + doing +
                               " failed: " + error);
    }
  } // namespace app
} // namespace formsolve
