#include <deal.II/base/exceptions.h>

#include <formsolve/material/yield_fit.h>
#include <formsolve/material/yld2004.h>
#include <formsolve/parameters/anisotropy.h>

#include <unsupported/Eigen/LevenbergMarquardt>
#include <unsupported/Eigen/NumericalDiff>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

namespace formsolve
{
  namespace material
  {
    namespace
    {
      enum class Kind
      {
        stress,
        r,
        biaxial_stress,
        biaxial_r,
        plane_strain
      };

      struct Datum
      {
        Kind        kind;
        double      angle; // degrees, for the directional tests
        double      value;
        std::string key;
      };

      std::string angle_key(const double a)
      {
        std::ostringstream s;
        s << a;
        return s.str();
      }

      std::vector<Datum> data_of(const parameters::YieldFit &f)
      {
        std::vector<Datum> d;
        for (std::size_t i = 0; i < f.stress_ratios.size(); ++i)
          if (f.angles[i] != 0)
            d.push_back({Kind::stress,
                         f.angles[i],
                         f.stress_ratios[i],
                         "stress_ratio_" + angle_key(f.angles[i])});
        for (std::size_t i = 0; i < f.r_values.size(); ++i)
          d.push_back({Kind::r,
                       f.angles[i],
                       f.r_values[i],
                       "r" + angle_key(f.angles[i])});
        for (const double x : f.biaxial_stress_ratio)
          d.push_back({Kind::biaxial_stress, 0, x, "stress_ratio_biaxial"});
        for (const double x : f.biaxial_r_value)
          d.push_back({Kind::biaxial_r, 0, x, "r_biaxial"});
        for (const double x : f.plane_strain_ratio)
          d.push_back({Kind::plane_strain, 0, x, "stress_ratio_plane_strain"});
        return d;
      }

      double model_value(const Yld2004 &f, const Datum &d)
      {
        const double angle = d.angle * M_PI / 180;
        switch (d.kind)
          {
            case Kind::stress:
              return f.stress_ratio(angle);
            case Kind::r:
              return f.r_value(angle);
            case Kind::biaxial_stress:
              return f.biaxial_ratio();
            case Kind::biaxial_r:
              return f.biaxial_r();
            case Kind::plane_strain:
              return f.plane_strain_ratio();
          }
        return 0;
      }

      /// The 14 unknowns (c12 ... c32, c66 of C', then of C'') into the
      /// nine coefficients of each, c44 and c55 from @p start.
      void unpack(const Eigen::VectorXd &x,
                  std::vector<double>   &c1,
                  std::vector<double>   &c2)
      {
        for (unsigned int k = 0; k < 6; ++k)
          {
            c1[k] = x[k];
            c2[k] = x[7 + k];
          }
        c1[8] = x[6];
        c2[8] = x[13];
      }

      /// Eigen's functor protocol: 14 inputs, one relative error per datum.
      struct Residual
      {
        using Scalar = double;
        enum
        {
          InputsAtCompileTime = Eigen::Dynamic,
          ValuesAtCompileTime = Eigen::Dynamic
        };
        using InputType    = Eigen::VectorXd;
        using ValueType    = Eigen::VectorXd;
        using JacobianType = Eigen::MatrixXd;
        using QRSolver     = Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;

        const std::vector<Datum> &data;
        std::vector<double>       c1, c2;
        double                    exponent;
        double                    scale       = 1; // |x|^2 of the start
        mutable unsigned int      evaluations = 0;

        int inputs() const { return 14; }
        int values() const { return data.size() + 1; }

        int operator()(const Eigen::VectorXd &x, Eigen::VectorXd &r) const
        {
          ++evaluations;
          std::vector<double> a = c1, b = c2;
          unpack(x, a, b);
          const Yld2004 f(a, b, exponent);
          for (std::size_t i = 0; i < data.size(); ++i)
            {
              const double m = model_value(f, data[i]);
              // A set without an RD yield stress or a flat point: a large
              // error that Levenberg-Marquardt steps back from.
              r[i] = std::isfinite(m) ? m / data[i].value - 1 : 1e3;
            }
          // C' and C'' scaled together (by any non-zero factor) give the
          // same normalised criterion: fix the scale to the start's.
          r[data.size()] = x.squaredNorm() / scale - 1;
          return 0;
        }
      };

      std::string coefficient_list(const std::vector<double> &c,
                                   const bool                 nine)
      {
        std::ostringstream s;
        s.precision(6);
        for (unsigned int k = 0; k < 9; ++k)
          if (nine || (k != 6 && k != 7))
            s << (k ? ", " : "") << c[k];
        return s.str();
      }
    } // namespace

    YldFit fit_yld2004(const parameters::Anisotropy &p)
    {
      const std::vector<Datum>  data = data_of(p.fit);
      const std::vector<double> c1   = p.yld_coefficients(1),
                                c2   = p.yld_coefficients(2);
      Eigen::VectorXd x(14);
      for (unsigned int k = 0; k < 6; ++k)
        {
          x[k]     = c1[k];
          x[7 + k] = c2[k];
        }
      x[6]  = c1[8];
      x[13] = c2[8];
      Residual residual{data, c1, c2, p.yield_exponent, x.squaredNorm()};

      // Levenberg-Marquardt finds the nearest minimum, and the sum of
      // squares has many: start also from fixed pseudo-random perturbations
      // of the given set (the same on every rank) and keep the best; stop
      // early once the data are met to rounding.
      Eigen::NumericalDiff<Residual, Eigen::Forward> differences(residual);
      Eigen::VectorXd                                fvec(residual.values());
      std::mt19937                                   random(2004);
      double                best  = std::numeric_limits<double>::max();
      const Eigen::VectorXd start = x;
      for (unsigned int k = 0; k < p.fit.starts && best > 1e-20; ++k)
        {
          Eigen::VectorXd y = start;
          if (k > 0)
            for (Eigen::Index i = 0; i < y.size(); ++i)
              y[i] += 1.2 * (random() / 4294967296. - 0.5);
          Eigen::LevenbergMarquardt<decltype(differences)> lm(differences);
          lm.setMaxfev(2000);
          lm.minimize(y);
          differences(y, fvec);
          if (fvec.squaredNorm() < best)
            {
              best = fvec.squaredNorm();
              x    = y;
            }
        }

      YldFit out;
      out.c1 = residual.c1;
      out.c2 = residual.c2;
      unpack(x, out.c1, out.c2);
      out.evaluations = differences.evaluations;
      const Yld2004      f(out.c1, out.c2, p.yield_exponent);
      std::ostringstream s;
      const bool         nine = p.yld_c1.size() == 9;
      s << "yld_fit_c1 = " << coefficient_list(out.c1, nine)
        << "\nyld_fit_c2 = " << coefficient_list(out.c2, nine);
      unsigned int n_stress = 0, n_r = 0;
      for (const Datum &d : data)
        {
          const double m = model_value(f, d);
          AssertThrow(std::isfinite(m),
                      dealii::ExcMessage(
                        "Material/Yld2004-18p fit: the least-squares fit "
                        "found no Yld2004-18p set with a yield stress in " +
                        d.key +
                        "; check the data or start from other "
                        "Yld2004-18p C1, C2"));
          const bool is_r = d.kind == Kind::r || d.kind == Kind::biaxial_r;
          (is_r ? out.rms_r : out.rms_stress) += (m - d.value) * (m - d.value);
          ++(is_r ? n_r : n_stress);
          s << "\nfit_" << d.key << " = " << m << "\ndata_" << d.key << " = "
            << d.value;
        }
      out.rms_stress = std::sqrt(out.rms_stress / std::max(1u, n_stress));
      out.rms_r      = std::sqrt(out.rms_r / std::max(1u, n_r));
      s << "\nyld_fit_rms_stress_ratio = " << out.rms_stress
        << "\nyld_fit_rms_r_value = " << out.rms_r
        << "\nyld_fit_evaluations = " << out.evaluations;
      out.report = s.str();
      std::ostringstream h;
      h << "Yld2004-18p fitted to " << data.size() << " data by least squares: "
        << "RMS error " << out.rms_stress << " in stress ratios, " << out.rms_r
        << " in r-values; C' = " << coefficient_list(out.c1, nine)
        << "; C'' = " << coefficient_list(out.c2, nine);
      out.headline = h.str();
      return out;
    }
  } // namespace material
} // namespace formsolve
