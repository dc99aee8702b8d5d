// gradcontact/fem: the one way the solvers write their fields for ParaView.
#ifndef GRADCONTACT_FEM_VTU_OUTPUT_H
#define GRADCONTACT_FEM_VTU_OUTPUT_H

#include <deal.II/fe/mapping.h>
#include <deal.II/numerics/data_out.h>

#include <string>

namespace gradcontact::fem
{
  /// Builds the patches of `data_out` (its vectors attached) with `degree` subdivisions per cell on
  /// `mapping` and writes them to `filename` as VTU; std::runtime_error naming `who` and the file when
  /// it cannot be written.
  void write_vtu(dealii::DataOut<2> &data_out, const dealii::Mapping<2> &mapping, unsigned int degree,
                 const std::string &filename, const std::string &who);
} // namespace gradcontact::fem

#endif
