// The mapping of the current configuration: the reference mapping plus the
// displacement, with the support points computed once per displacement
// (MappingQCache) instead of at every FEValues::reinit (MappingQEulerian,
// which reads them from the Trilinos vector each time: 10 % of a 3-D run).
// Like MappingQEulerian, and unlike MappingQCache in deal.II 9.4, it never
// reuses a previous cell's Jacobians: FEValues calls two cells "similar"
// when their *reference* vertices are translates, which says nothing about
// the deformed cells (the axisymmetric section's rectangles lost 0.14 % of
// their volume per step that way).
#pragma once

#include <deal.II/fe/mapping_q_cache.h>

namespace formsolve
{
  namespace model
  {
    template <int dim>
    class CurrentMapping : public dealii::MappingQCache<dim>
    {
    public:
      explicit CurrentMapping(const unsigned int degree);

      std::unique_ptr<dealii::Mapping<dim>> clone() const override;

    protected:
      dealii::CellSimilarity::Similarity fill_fe_values(
        const typename dealii::Triangulation<dim>::cell_iterator &cell,
        const dealii::CellSimilarity::Similarity               cell_similarity,
        const dealii::Quadrature<dim>                         &quadrature,
        const typename dealii::Mapping<dim>::InternalDataBase &internal_data,
        dealii::internal::FEValuesImplementation::MappingRelatedData<dim>
          &output_data) const override;
    };
  } // namespace model
} // namespace formsolve
