#ifndef tribodyn_core_morphology_source_h
#define tribodyn_core_morphology_source_h

#include <algorithm>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <tribodyn/core/morphology.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/plugin_registry.h>
#include <vector>

namespace tribodyn
{
  /**
   * The morphology sources of one dimension (`Morphology/Generator`), each
   * registered from its own file (ASPECT's way):
   *
   *   static const bool laminate_registered = SourceRegistry<Source>::add(
   *     {"laminate", 3, "layers through the whole rectangle",
   *      [] { return std::make_unique<LaminateMorphology>(); }});
   *
   * The entry `Generator` is built from the list: its choices in the order
   * of the `order` keys (static initialization runs in an unspecified
   * order across files, so the list is sorted), its documentation from
   * each source's text. A new source touches no shared file.
   */
  template <typename Source>
  class SourceRegistry
  {
  public:
    using Common = typename Source::Common;

    struct Entry
    {
      std::string name;
      /// Position among the choices (documentation and pattern).
      double order = 0;
      /// What the source makes, for the documentation of `Generator`.
      std::string                              documentation;
      std::function<std::unique_ptr<Source>()> create;
    };

    /// Add @p entry; returns true (for a static initializer). A name
    /// registered twice is a programming error (std::logic_error).
    static bool
    add(Entry entry)
    {
      add_registered(entries(), std::move(entry), "morphology sources");
      return true;
    }

    /// The registered sources, in order.
    static const std::vector<Entry> &
    list()
    {
      return entries();
    }

    /// A new source of the registered @p name, with its defaults.
    static std::unique_ptr<Source>
    create(const std::string &name)
    {
      for (const Entry &e : entries())
        if (e.name == name)
          return e.create();
      // The entry's pattern lists the names: only a caller's typo gets
      // here.
      throw std::logic_error("no morphology source is registered as '" + name
                             + "'");
    }

    /// The names, separated by '|' (a Patterns::Selection).
    static std::string
    pattern()
    {
      std::string p;
      for (const Entry &e : entries())
        p += (p.empty() ? "" : "|") + e.name;
      return p;
    }

    /// "'a' (what a makes), 'b' (...)", for the entry's documentation.
    static std::string
    choices()
    {
      std::string d;
      for (const Entry &e : entries())
        d += (d.empty() ? "'" : ", '") + e.name + "' (" + e.documentation + ")";
      return d;
    }

    /// Bind the entry `Generator` in @p b: one of the registered names
    /// (@p default_name by default), documented as @p introduction then
    /// each one's text; reading it makes the named source in @p chosen.
    static void
    add_generator_entry(ParameterBinding        &b,
                        const std::string       &default_name,
                        const std::string       &introduction,
                        std::unique_ptr<Source> &chosen)
    {
      b.add("Generator",
            default_name,
            introduction + choices() + ".",
            dealii::Patterns::Selection(pattern()),
            [&chosen](const std::string &name) { chosen = create(name); });
    }

    /// Declare every registered source's entries of "Morphology" and its
    /// subsections (@p prm at the top level).
    static void
    declare_sources(dealii::ParameterHandler &prm)
    {
      for (const Entry &e : entries())
        {
          const std::unique_ptr<Source> source = e.create();
          ParameterBinding              own("Morphology");
          source->bind(own);
          own.declare(prm);
          source->declare_subsections(prm);
        }
    }

    /// Read the entries of @p chosen (the source `Generator` named), then
    /// let it read its subsections and check its values against
    /// @p common (Source::parse(); @p b: the common entries' binding).
    static std::shared_ptr<const Source>
    parse_chosen(std::unique_ptr<Source>   chosen,
                 dealii::ParameterHandler &prm,
                 const ParameterBinding   &b,
                 Common                   &common)
    {
      ParameterBinding own("Morphology");
      chosen->bind(own);
      own.parse(prm);
      chosen->parse(prm, b, common);
      return chosen;
    }

  private:
    static std::vector<Entry> &
    entries()
    {
      static std::vector<Entry> list;
      return list;
    }
  };


  /**
   * One way to make the map of the subsection "Morphology" (a generator or a
   * file reader), with its own parameters: of a 2D map (Morphology, from
   * MorphologyParameters: MorphologySource) or of a voxel volume
   * (homogenization::VolumeSource). A source is one file that registers
   * itself in its SourceRegistry.
   */
  template <typename Map, typename CommonParameters>
  class SourceBase
  {
  public:
    /// The entries common to the sources (size, pixels, seed, ...).
    using Common = CommonParameters;

    virtual ~SourceBase() = default;

    /// Bind its own entries of "Morphology" in @p b (every source's are
    /// declared; the chosen one's are read).
    virtual void
    bind(ParameterBinding &)
    {
    }

    /// Declare its subsections of "Morphology" (the handler at the top
    /// level), if it has any.
    virtual void
    declare_subsections(dealii::ParameterHandler &) const
    {
    }

    /**
     * After its entries are read, when it is chosen: read its subsections,
     * check its values (against the common ones of @p common; @p b is the
     * subsection's binding, for the paths in messages), and record in
     * @p common and in @p prm what it fixes (a file's pixels), so that
     * parameters.prm says what the run used.
     */
    virtual void
    parse(dealii::ParameterHandler &, const ParameterBinding &, Common &)
    {
    }

    /// The map.
    virtual Map
    create(const Common &common) const = 0;

    /// Whether the map depends on `Morphology/Seed` (a study or an
    /// RVE-size study draws new maps by changing it).
    virtual bool
    uses_seed() const
    {
      return false;
    }
  };


  /**
   * A source of the 2D engines' material map. Its file is in
   * `source/core/morphology_sources/`; its header (beside the others in
   * `include/tribodyn/core/morphology_sources/`) is needed only by code
   * that sets its parameters without a parameter file (tests, the study's
   * windows: MorphologyParameters::use(), edit()).
   */
  class MorphologySource : public SourceBase<Morphology, MorphologyParameters>
  {
  public:
    /// Whether the map is read from a file rather than generated: it may
    /// hold any number of phases, and a study cuts windows from it.
    virtual bool
    is_map() const;

    /// The entry that fixes the map's number of phases (an image's
    /// segmentation), if any: the materials must then name exactly that
    /// many; otherwise at least as many as the largest id + 1.
    virtual std::string
    phases_set_by() const;
  };

  /// The 2D morphology sources.
  using MorphologySources = SourceRegistry<MorphologySource>;
} // namespace tribodyn

#endif
