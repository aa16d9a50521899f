#include <deal.II/base/exceptions.h>

#include <formsolve/model/model.h>

namespace formsolve
{
  namespace model
  {
    std::string model_names()
    {
      return "axisymmetric|plane strain|half|quarter|full|slice";
    }

    Model parse_model(const std::string &n)
    {
      if (n == "axisymmetric")
        return Model::axisymmetric;
      if (n == "plane strain")
        return Model::plane_strain;
      if (n == "half")
        return Model::half;
      if (n == "slice")
        return Model::slice;
      if (n == "quarter")
        return Model::quarter;
      AssertThrow(n == "full",
                  dealii::ExcMessage("Parameter Geometry/Model: '" + n +
                                     "' is not one of " + model_names()));
      return Model::full;
    }

    std::string name(const Model m)
    {
      switch (m)
        {
          case Model::axisymmetric:
            return "axisymmetric";
          case Model::plane_strain:
            return "plane strain";
          case Model::half:
            return "half";
          case Model::quarter:
            return "quarter";
          case Model::full:
            return "full";
          case Model::slice:
            return "slice";
        }
      return "";
    }

    std::vector<std::string> coordinate_names(const Model m)
    {
      if (m == Model::axisymmetric)
        return {"r", "z"};
      if (m == Model::plane_strain)
        return {"x", "z"};
      return {"x", "y", "z"};
    }

    unsigned int space_dimension(const Model m)
    {
      return m == Model::axisymmetric || m == Model::plane_strain ? 2 : 3;
    }

    double symmetry_factor(const Model m)
    {
      if (m == Model::quarter)
        return 4.;
      return m == Model::half || m == Model::plane_strain || m == Model::slice
               ? 2.
               : 1.;
    }

    bool symmetric_in_x(const Model m)
    {
      return m == Model::half || m == Model::quarter ||
             m == Model::plane_strain || m == Model::slice;
    }

    bool symmetric_in_y(const Model m)
    {
      return m == Model::quarter || m == Model::slice;
    }
  } // namespace model
} // namespace formsolve
