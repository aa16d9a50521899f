// What the contact search finds at one velocity iterate: sheet surface nodes
// near each tool, with gaps, normals, areas and status.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <vector>

namespace formsolve
{
  namespace contact
  {
    using dealii::Point;
    using dealii::Tensor;

    /// A sheet surface node: its velocity DoFs and reference position.
    template <int dim>
    struct ContactNode
    {
      std::array<dealii::types::global_dof_index, dim> dofs;
      Point<dim>                                       reference_position;
      /// Lumped area vector int phi_k n dA over the sheet surface (mm^2),
      /// current configuration (the full ring in axisymmetry): its
      /// projection on a tool normal is the node's share of the surface
      /// facing that tool.
      Tensor<1, dim> area_vector;
    };

    /// One node near one tool, evaluated at the current velocity iterate.
    template <int dim>
    struct ContactPair
    {
      unsigned int   node;
      unsigned int   tool;
      double         gap; // signed distance at the start of the step (mm)
      double         predicted_gap; // gap + n.(v - v_tool) dt (mm)
      Tensor<1, dim> normal;        // outward tool normal at the closest point
      Tensor<1, dim> relative_velocity; // v - v_tool (mm/s)
      double         area;   // projected nodal area facing the tool (mm^2)
      bool           active; // predicted_gap < shift
      bool           locked = false; // ContactState::track_status: frozen
      /// Augmented Lagrangian: multiplier as a gap shift s = lambda/eps (mm),
      /// read from the contact state; the normal force is eps <s - g_pred>.
      double shift = 0;
    };

    template <int dim>
    struct ContactSet
    {
      std::vector<ContactNode<dim>> nodes; // locally owned surface nodes
      std::vector<ContactPair<dim>> pairs; // pairs within the search distance

      unsigned int n_active() const
      {
        unsigned int n = 0;
        for (const auto &p : pairs)
          n += p.active;
        return n;
      }
    };
  } // namespace contact
} // namespace formsolve
