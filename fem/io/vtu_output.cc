#include <fem/io/vtu_output.h>

#include <fstream>
#include <stdexcept>

namespace gradcontact::fem
{
  const std::vector<MeridianDataOut::Patch> &MeridianDataOut::get_patches() const
  {
    return surface_map.active() ? mapped : dealii::DataOut<2>::get_patches();
  }



  void MeridianDataOut::map_patches()
  {
    mapped.clear();
    if (!surface_map.active())
      return;
    mapped = dealii::DataOut<2>::get_patches();
    for (Patch &patch : mapped)
      {
        const unsigned int n       = patch.n_subdivisions + 1;
        const unsigned int n_rows  = patch.data.n_rows();
        const unsigned int n_data  = patch.points_are_available ? n_rows - 2 : n_rows;
        // The points of the patch, lexicographic (x fastest): given, or bilinear in the vertices.
        dealii::Table<2, float> data(n_data + 2, n * n);
        for (unsigned int row = 0; row < n_data; ++row)
          for (unsigned int j = 0; j < n * n; ++j)
            data(row, j) = patch.data(row, j);
        for (unsigned int iy = 0; iy < n; ++iy)
          for (unsigned int ix = 0; ix < n; ++ix)
            {
              const unsigned int j = iy * n + ix;
              dealii::Point<2>   x;
              if (patch.points_are_available)
                x = dealii::Point<2>(patch.data(n_data, j), patch.data(n_data + 1, j));
              else
                {
                  const double s = (n > 1) ? double(ix) / (n - 1) : 0.0, t = (n > 1) ? double(iy) / (n - 1) : 0.0;
                  for (unsigned int d = 0; d < 2; ++d)
                    x[d] = (1 - s) * (1 - t) * patch.vertices[0][d] + s * (1 - t) * patch.vertices[1][d] +
                           (1 - s) * t * patch.vertices[2][d] + s * t * patch.vertices[3][d];
                }
              const dealii::Point<2> p = surface_map.physical(x);
              data(n_data, j)          = p[0];
              data(n_data + 1, j)      = p[1];
            }
        for (auto &v : patch.vertices)
          v = surface_map.physical(v);
        patch.data.swap(data);
        patch.points_are_available = true;
      }
  }



  void write_vtu(MeridianDataOut &data_out, const dealii::Mapping<2> &mapping, const unsigned int degree,
                 const std::string &filename, const std::string &who)
  {
    data_out.build_patches(mapping, degree);
    data_out.map_patches();
    std::ofstream out(filename);
    if (!out)
      throw std::runtime_error(who + ": cannot write " + filename);
    data_out.write_vtu(out);
  }
} // namespace gradcontact::fem
