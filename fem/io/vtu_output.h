// gradcontact/fem: the one way the solvers write their fields for ParaView.
#ifndef GRADCONTACT_FEM_VTU_OUTPUT_H
#define GRADCONTACT_FEM_VTU_OUTPUT_H

#include <fem/modulus/surface_map.h>

#include <deal.II/base/point.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/numerics/data_out.h>

#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// DataOut of the meridian plane whose patches are written at physical points: the mesh coordinates
  /// through `surface_map` (fem/modulus/surface_map.h; the identity by default).
  class MeridianDataOut : public dealii::DataOut<2>
  {
  public:
    SurfaceMap<2> surface_map;

    const std::vector<Patch> &get_patches() const override;

    /// Moves every patch point through the surface map (call after build_patches).
    void map_patches();

  private:
    std::vector<Patch> mapped;
  };

  /// Builds the patches of `data_out` (its vectors attached) with `degree` subdivisions per cell on
  /// `mapping`, maps them to physical points, and writes them to `filename` as VTU; std::runtime_error
  /// naming `who` and the file when it cannot be written.
  void write_vtu(MeridianDataOut &data_out, const dealii::Mapping<2> &mapping, unsigned int degree,
                 const std::string &filename, const std::string &who);
} // namespace gradcontact::fem

#endif
