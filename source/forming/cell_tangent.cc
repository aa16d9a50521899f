#include <formsolve/forming/cell_tangent.h>
#include <formsolve/material/mandel.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace solver
  {
    using namespace dealii;

    template <int dim>
    CellTangent<dim>::CellTangent(const FiniteElement<dim> &fe,
                                  const unsigned int        n_points,
                                  const unsigned int        n_reduced_points,
                                  const bool                hoop)
        : n_psi(dim + (hoop ? 1 : 0))
        , hoop(hoop)
    {
      const unsigned int n = fe.n_dofs_per_cell();
      component.resize(n);
      node.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          component[i] = fe.system_to_component_index(i).first;
          node[i]      = fe.system_to_component_index(i).second;
        }
      Assert(fe.n_components() == dim && n % dim == 0, ExcInternalError());
      const unsigned int n_scalar = n / dim;
      psi.reinit(n_points, n_scalar * n_psi);
      psi_w.reinit(n_points, n_scalar * n_psi);
      S.reinit(n_points, n);
      U.reinit(n_points, n);
      T.reinit(n_reduced_points, n);
      T_w.reinit(n_reduced_points, n);
      P.reinit(n_scalar * n_psi, n_scalar * n_psi);
      E.reinit(n, n);
      V.reinit(n, n);
      G.reinit(6 * n_points, n);
      CG.reinit(6 * n_points, n);
    }

    template <int dim>
    void
    CellTangent<dim>::add_deviatoric(const unsigned int                     q,
                                     const std::vector<model::ShapeStrain> &B,
                                     const double                           mu,
                                     const std::vector<double>             &s,
                                     const std::vector<double>             &u)
    {
      // The components of one node share the scalar gradient: take it (and
      // phi/r, carried by the radial component) from component 0.
      product_form = true;
      for (unsigned int i = 0; i < B.size(); ++i)
        {
          if (component[i] == 0)
            {
              for (unsigned int k = 0; k < dim; ++k)
                {
                  psi(q, column(node[i], k))   = B[i].gradient[k];
                  psi_w(q, column(node[i], k)) = mu * B[i].gradient[k];
                }
              if (hoop)
                {
                  psi(q, column(node[i], dim))   = B[i].hoop;
                  psi_w(q, column(node[i], dim)) = mu * B[i].hoop;
                }
            }
          S(q, i) = s[i];
          U(q, i) = u[i];
        }
    }

    template <int dim>
    void CellTangent<dim>::add_general(const unsigned int                     q,
                                       const std::vector<model::ShapeStrain> &B,
                                       const SymmetricTensor<4, 3>           &C)
    {
      add_general(q, B, material::to_mandel(C), 1.);
    }

    template <int dim>
    void CellTangent<dim>::add_general(const unsigned int                     q,
                                       const std::vector<model::ShapeStrain> &B,
                                       const material::Mandel6x6 &C6,
                                       const double               weight)
    {
      general_form       = true;
      const double root2 = std::sqrt(2.);
      for (unsigned int i = 0; i < B.size(); ++i)
        {
          // B_i = sym(e_c (x) g) + hoop e_2 (x) e_2 in Mandel's entries.
          const unsigned int c = B[i].component;
          material::Mandel6  b{};
          for (unsigned int r = 0; r < 6; ++r)
            {
              const unsigned int k = material::mandel_index[r][0],
                                 l = material::mandel_index[r][1];
              if (k == l)
                b[r] = k == c ? B[i].gradient[c] : 0.;
              else if (k == c || l == c)
                b[r] = root2 * 0.5 * B[i].gradient[k == c ? l : k];
            }
          b[2] += B[i].hoop;
          for (unsigned int r = 0; r < 6; ++r)
            {
              double cb = 0;
              for (unsigned int s = 0; s < 6; ++s)
                cb += C6[r][s] * b[s];
              G(6 * q + r, i)  = b[r];
              CG(6 * q + r, i) = weight * cb;
            }
        }
    }

    template <int dim>
    void CellTangent<dim>::add_volumetric(const unsigned int         q,
                                          const std::vector<double> &tr,
                                          const double               weight)
    {
      for (unsigned int i = 0; i < tr.size(); ++i)
        {
          T(q, i)   = tr[i];
          T_w(q, i) = weight * tr[i];
        }
    }

    template <int dim>
    void CellTangent<dim>::finish(FullMatrix<double> &K)
    {
      T.Tmmult(V, T_w);
      if (general_form)
        {
          // G^T (C G) plus the volumetric term: the product form's parts
          // are zero.
          Assert(!product_form, ExcInternalError());
          G.Tmmult(K, CG);
          K.add(1., V);
          G            = 0;
          CG           = 0;
          T            = 0;
          T_w          = 0;
          general_form = false;
          return;
        }
      product_form = false;
      psi.Tmmult(P, psi_w);
      S.Tmmult(E, U);
      const unsigned int n = component.size();
      const unsigned int h = dim; // the phi/r column
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            const unsigned int a = node[i], c = component[i];
            const unsigned int b = node[j], d = component[j];
            // 2 mu B_i : B_j with B_i = sym(e_c (x) g_a) + hoop
            // = mu (delta_cd g_a.g_b + g_a[d] g_b[c]) + 2 mu h_i h_j.
            double bb = P(column(a, d), column(b, c));
            if (c == d)
              for (unsigned int k = 0; k < dim; ++k)
                bb += P(column(a, k), column(b, k));
            // mu tr_i tr_j with tr_i = g_a[c] + h_i.
            double tt = P(column(a, c), column(b, d));
            if (hoop)
              {
                const double hh = P(column(a, h), column(b, h));
                if (c == 0 && d == 0)
                  bb += 2. * hh, tt += hh;
                if (d == 0)
                  tt += P(column(a, c), column(b, h));
                if (c == 0)
                  tt += P(column(a, h), column(b, d));
              }
            K(i, j) = bb - 2. / 3. * tt + E(i, j) + E(j, i) + V(i, j);
          }
      psi   = 0;
      psi_w = 0;
      S     = 0;
      U     = 0;
      T     = 0;
      T_w   = 0;
    }

#define INSTANTIATE(dim) template class CellTangent<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace solver
} // namespace formsolve
