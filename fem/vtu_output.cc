#include <fem/vtu_output.h>

#include <fstream>
#include <stdexcept>

namespace gradcontact::fem
{
  void write_vtu(dealii::DataOut<2> &data_out, const dealii::Mapping<2> &mapping, const unsigned int degree,
                 const std::string &filename, const std::string &who)
  {
    data_out.build_patches(mapping, degree);
    std::ofstream out(filename);
    if (!out)
      throw std::runtime_error(who + ": cannot write " + filename);
    data_out.write_vtu(out);
  }
} // namespace gradcontact::fem
