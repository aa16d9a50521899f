// The predictor at the contact nodes (contact::keep_contact): a pair that was
// in contact at the end of the last solve and that the predictor opens is
// moved along its tool normal to touch (predicted gap = shift less
// touch_depth of the tool's allowed penetration);
// pairs that stay closed, pairs not in contact before and surface that does
// not face the tool keep their velocity.
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <formsolve/contact/contact_predictor.h>
#include <formsolve/parameters/contact.h>
#include <formsolve/parameters/tools.h>

#include "check.h"

using namespace dealii;
using namespace formsolve::contact;

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     dt = 0.25;

  // Punch (tool 0) and die (tool 1) with different allowed penetrations.
  formsolve::parameters::Tools tool_prm;
  tool_prm.punch.allowed_penetration = 1e-3;
  tool_prm.die.allowed_penetration   = 4e-3;
  tool_prm.blank_holder.enabled      = false;
  const formsolve::tools::ToolSet<3> tools(tool_prm,
                                           formsolve::parameters::Contact(),
                                           1.);
  const double touch[] = {touch_depth * 1e-3, touch_depth * 4e-3};

  ContactSet<3> set;
  set.nodes.resize(5);
  for (unsigned int k = 0; k < 5; ++k)
    for (unsigned int a = 0; a < 3; ++a)
      set.nodes[k].dofs[a] = 3 * k + a;

  Tensor<1, 3> n; // a tool normal that is not a coordinate axis
  n[0] = 0.6, n[2] = 0.8;
  const auto pair = [&](const unsigned int node,
                        const unsigned int tool,
                        const double       predicted_gap,
                        const double       shift,
                        const double       area) {
    ContactPair<3> p;
    p.node = node, p.tool = tool, p.gap = predicted_gap, p.normal = n;
    p.predicted_gap = predicted_gap, p.shift = shift, p.area = area;
    p.active = predicted_gap <= shift && area > 0;
    return p;
  };
  set.pairs = {
    pair(0, 0, 2e-3, 0, 1),    // was in contact, opened: touch
    pair(1, 0, -1e-3, 0, 1),   // was in contact, still closed: keep
    pair(2, 1, 2e-3, 0, 1),    // was not in contact: keep
    pair(3, 1, 3e-3, 5e-4, 1), // augmented Lagrangian shift: touch at it
    pair(4, 0, 2e-3, 0, 0),    // does not face the tool: keep
  };
  ContactState state;
  state.reset(5, 2);
  state(0, 0).active = state(1, 0).active = state(3, 1).active = true;
  state(4, 0).active                                           = true;

  TrilinosWrappers::MPI::Vector change(complete_index_set(15), MPI_COMM_WORLD);
  const unsigned int moved = keep_contact(set, state, tools, dt, change);
  change.compress(VectorOperation::add);

  test::close("pairs moved", moved, 2, 0);
  const double expected_gap[] = {-touch[0], -1e-3, 2e-3, 5e-4 - touch[1], 2e-3};
  for (unsigned int k = 0; k < 5; ++k)
    {
      Tensor<1, 3> dv;
      for (unsigned int a = 0; a < 3; ++a)
        dv[a] = change[3 * k + a];
      const auto &p = set.pairs[k];
      test::close("node " + std::to_string(k) + ": predicted gap after",
                  p.predicted_gap + (n * dv) * dt,
                  expected_gap[k],
                  1e-15);
      test::close("node " + std::to_string(k) + ": no tangential change",
                  (dv - (dv * n) * n).norm(),
                  0,
                  1e-15);
    }
  return test::result();
}
