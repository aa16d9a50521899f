#include <formsolve/model/current_mapping.h>
#include <formsolve/model/dimensions.h>

namespace formsolve
{
  namespace model
  {
    using namespace dealii;

    template <int dim>
    CurrentMapping<dim>::CurrentMapping(const unsigned int degree)
        : MappingQCache<dim>(degree)
    {}

    template <int dim>
    std::unique_ptr<Mapping<dim>> CurrentMapping<dim>::clone() const
    {
      return std::make_unique<CurrentMapping<dim>>(*this);
    }

    template <int dim>
    CellSimilarity::Similarity CurrentMapping<dim>::fill_fe_values(
      const typename Triangulation<dim>::cell_iterator &cell,
      const CellSimilarity::Similarity,
      const Quadrature<dim>                                     &quadrature,
      const typename Mapping<dim>::InternalDataBase             &internal_data,
      internal::FEValuesImplementation::MappingRelatedData<dim> &output_data)
      const
    {
      MappingQCache<dim>::fill_fe_values(cell,
                                         CellSimilarity::invalid_next_cell,
                                         quadrature,
                                         internal_data,
                                         output_data);
      return CellSimilarity::invalid_next_cell;
    }

#define INSTANTIATE(dim) template class CurrentMapping<dim>;
    FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#undef INSTANTIATE
  } // namespace model
} // namespace formsolve
