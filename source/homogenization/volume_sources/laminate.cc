// The volume source 'laminate': layers through the whole box.
#include <cmath>
#include <tribodyn/core/errors.h>
#include <tribodyn/homogenization/volume_source.h>

namespace tribodyn
{
  namespace homogenization
  {
    namespace
    {
      class LaminateVolume : public VolumeSource
      {
      public:
        /// Axis of the layers' normal (0 = x, 1 = y, 2 = z) and the number
        /// of (matrix, heterogeneity) periods along it.
        unsigned int normal  = 2;
        unsigned int periods = 1;

        void
        bind(ParameterBinding &b) override
        {
          b.add("Laminate normal",
                normal,
                "Laminate: the axis normal to the layers.",
                axis_choices);
          b.add("Laminate periods",
                periods,
                "Laminate: number of (matrix, heterogeneity) periods along "
                "the normal; it must divide the number of voxels along it.",
                dealii::Patterns::Integer(1));
        }

        void
        parse(dealii::ParameterHandler &,
              const ParameterBinding     &b,
              VolumeMorphologyParameters &p) override
        {
          check_parameter(p.n_voxels[normal] % periods == 0,
                          b.path("Laminate periods"),
                          "it must divide the number of voxels along the "
                          "normal ("
                            + std::to_string(p.n_voxels[normal])
                            + "), so that every layer ends on a voxel face.");
        }

        /// In each period of p voxels along the normal, the first
        /// round(f p) are heterogeneity (id 1).
        VoxelVolume
        create(const VolumeMorphologyParameters &p) const override
        {
          const unsigned int a      = normal;
          const unsigned int period = p.n_voxels[a] / periods;
          const unsigned int thick  = static_cast<unsigned int>(
            std::lround(p.volume_fraction * period));
          std::vector<std::uint8_t> ids(std::size_t(p.n_voxels[0])
                                        * p.n_voxels[1] * p.n_voxels[2]);
          std::size_t               v = 0;
          for (unsigned int k = 0; k < p.n_voxels[2]; ++k)
            for (unsigned int j = 0; j < p.n_voxels[1]; ++j)
              for (unsigned int i = 0; i < p.n_voxels[0]; ++i, ++v)
                {
                  const unsigned int index[3] = {i, j, k};
                  ids[v] = (index[a] % period) < thick ? 1 : 0;
                }
          return VoxelVolume(p.n_voxels,
                             {{p.voxel_size, p.voxel_size, p.voxel_size}},
                             std::move(ids),
                             "laminate normal to " + std::string(1, "xyz"[a])
                               + ", " + std::to_string(periods)
                               + " period(s) of " + std::to_string(period)
                               + " voxels, " + std::to_string(thick)
                               + " of them heterogeneity");
        }
      };
    } // namespace

    static const bool laminate_volume_registered = VolumeSources::add(
      {"laminate",
       1,
       "layers through the whole box, normal to 'Laminate normal'",
       [] { return std::make_unique<LaminateVolume>(); }});
  } // namespace homogenization
} // namespace tribodyn
