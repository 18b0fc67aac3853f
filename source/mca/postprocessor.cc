// The shared parts of the postprocessors (include/tribodyn/mca/
// postprocessor.h); each postprocessor is in source/mca/postprocessors/.
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/vector.hpp>
#include <tribodyn/mca/postprocessor.h>

namespace tribodyn
{
  namespace mca
  {
    void
    save_series(boost::archive::binary_oarchive          &ar,
                const std::vector<std::vector<double> *> &series)
    {
      for (const auto *s : series)
        ar << *s;
    }


    void
    load_series(boost::archive::binary_iarchive          &ar,
                const std::vector<std::vector<double> *> &series)
    {
      for (auto *s : series)
        ar >> *s;
    }
  } // namespace mca
} // namespace tribodyn
