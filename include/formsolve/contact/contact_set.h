// What the contact postprocessor finds: sheet surface nodes near tools.
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
      /// current configuration: its projection on a tool normal is the node's
      /// share of the surface facing that tool.
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
      bool           active; // predicted_gap < 0
      bool           locked = false; // status frozen by the chatter guard
      /// Augmented Lagrangian: multiplier as a gap shift s = lambda/eps (mm);
      /// the normal force is eps <s - predicted_gap>. Zero otherwise.
      double shift = 0;
    };

    template <int dim>
    struct ContactSet
    {
      std::vector<ContactNode<dim>> nodes; // locally owned surface nodes
      std::vector<ContactPair<dim>> pairs; // pairs within the search distance

      /// Status memory within a step: pair indices are stable within a step
      /// (the pairs depend on the start-of-step geometry only).
      std::vector<unsigned int> flips;  // status changes per pair
      std::vector<int>          locked; // -1 free, else the locked status
      std::vector<bool>         previous_active;

      /// Augmented Lagrangian gap shifts per (node, tool), index
      /// node * n_tools + tool; persistent across steps, empty if unused.
      std::vector<double> shifts;

      void begin_step()
      {
        flips.clear();
        locked.clear();
        previous_active.clear();
      }

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
