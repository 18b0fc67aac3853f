// The parameters of `set Problem = mca_study`: subsection Study and the
// study-wide Time/End time, declared and checked.

#include <algorithm>
#include <deal.II/base/utilities.h>
#include <set>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/output.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/study/mca_study.h>
#include <vector>

namespace tribodyn
{
  namespace study
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;

    namespace
    {

      std::string
      trim(const std::string &s)
      {
        return dealii::Utilities::trim(s);
      }


      /// "Path = value" items separated by ';' (@p parameter names the
      /// entry in messages).
      std::vector<std::pair<std::string, std::string>>
      path_assignments(const std::string &text, const std::string &parameter)
      {
        std::vector<std::pair<std::string, std::string>> items;
        for (const std::string &item :
             dealii::Utilities::split_string_list(text, ';'))
          {
            const auto eq = item.find('=');
            if (eq == std::string::npos || trim(item.substr(0, eq)).empty()
                || trim(item.substr(eq + 1)).empty())
              throw InputError(
                "'" + parameter + "': '" + item
                + "' is not of the form 'Subsection/Name = value' (items "
                  "separated by ';', e.g. 'Friction loading/Pressure = "
                  "150e6, 300e6; Time/Courant factor = 0.2').");
            items.emplace_back(trim(item.substr(0, eq)),
                               trim(item.substr(eq + 1)));
          }
        return items;
      }


      std::vector<unsigned int>
      seed_list(const std::string &text, const std::string &parameter)
      {
        std::vector<unsigned int> seeds;
        for (const std::string &item :
             dealii::Utilities::split_string_list(text, ','))
          {
            int value = -1;
            try
              {
                value = dealii::Utilities::string_to_int(item);
              }
            catch (...)
              {
                value = -1;
              }
            if (value < 0)
              throw InputError("'" + parameter + "': '" + item
                               + "' is not a seed (a non-negative integer). "
                                 "Give a comma-separated list, e.g. "
                                 "'1, 2, 3, 4'.");
            seeds.push_back(value);
          }
        return seeds;
      }
    } // namespace


    ParameterBinding
    McaStudyParameters::time_binding()
    {
      ParameterBinding b("Time");
      b.add("End time",
            end_time,
            "Simulated time of every scene (s), replacing the base files' "
            "'Time/End time'; 0 keeps each base's own. Raising it later "
            "continues the finished scenes from their last checkpoint (runs "
            "in legs).",
            Patterns::Double(0.));
      return b;
    }


    ParameterBinding
    McaStudyParameters::study_binding(const std::string &directory)
    {
      ParameterBinding b("Study");
      b.add("Bases",
            "steel: ../mca/friction_steel.prm, composite: "
            "../mca/friction_composite.prm",
            "The base scenes, 'name: file' separated by commas: parameter "
            "files of 'set Problem = mca' (their Output directory is replaced "
            "by the scene's). Relative paths are relative to the directory of "
            "the study's parameter file. Names are letters, digits, '-' and "
            "'_'.",
            Patterns::Anything(),
            [this, directory](const std::string &text) {
              read_bases(text, directory);
            });
      b.add("Reference base",
            reference,
            "The base the others are compared with, scene by scene on the "
            "same seeds and factor levels: (mu_base - mu_reference) / "
            "mu_reference. Empty: the first base.");
      b.add("Roughness seeds",
            "1",
            "Comma-separated seeds of the rough interface (Geometry/Rough "
            "interface/Seed): every base runs on each, and the differences "
            "are paired per seed. Add seeds until the mean difference's "
            "standard error is small enough.",
            Patterns::Anything(),
            [this, where = b.path("Roughness seeds")](const std::string &text) {
              roughness_seeds = seed_list(text, where);
            });
      b.add("Inclusion seeds",
            "",
            "Comma-separated seeds of the inclusions "
            "(Geometry/Inclusions/Seed), one per roughness seed, paired with "
            "it; empty: each equal to its roughness seed.",
            Patterns::Anything(),
            [this, where = b.path("Inclusion seeds")](const std::string &text) {
              inclusion_seeds = seed_list(text, where);
            });
      b.add("Factors",
            "",
            "Further factors, 'Subsection/Name = value, value, ...' "
            "separated by ';' (any parameter of the scenes by its path, e.g. "
            "'Friction loading/Pressure = 150e6, 300e6, 600e6'): the scenes "
            "are the bases x seeds x every combination of the factors' "
            "values.",
            Patterns::Anything(),
            [this, where = b.path("Factors")](const std::string &text) {
              read_factors(text, where);
            });
      b.add("Settings",
            "",
            "'Subsection/Name = value' separated by ';', set in every scene "
            "(e.g. 'Output/Write particles = false').",
            Patterns::Anything(),
            [this, where = b.path("Settings")](const std::string &text) {
              settings = path_assignments(text, where);
            });
      b.add("Checkpoint interval",
            checkpoint_interval,
            "Simulated time between two checkpoints of a scene (s), replacing "
            "the bases' 'Checkpoint/Interval': a study killed at any moment "
            "loses at most this much of each running scene. 0 keeps the "
            "bases' own.",
            Patterns::Double(0.));
      b.add("Ranks per scene",
            ranks_per_scene,
            "MPI ranks of each scene: the ranks form groups of this many (the "
            "remainder joins the last group), and the groups run scenes side "
            "by side.",
            Patterns::Integer(1));
      b.add("Plot script",
            plot_script,
            "Python script making the plots at the end: 'auto' looks for "
            "scripts/plot_mca_study next to the build directory (skipped when "
            "python3 or matplotlib is missing), 'none' makes no plots, or a "
            "path.");
      return b;
    }


    void
    McaStudyParameters::declare_parameters(ParameterHandler &prm)
    {
      McaStudyParameters defaults;
      defaults.time_binding().declare(prm);
      defaults.study_binding(".").declare(prm);
    }


    void
    McaStudyParameters::read_bases(const std::string &text,
                                   const std::string &directory)
    {
      bases.clear();
      for (const std::string &item :
           dealii::Utilities::split_string_list(text, ','))
        {
          const auto  colon = item.find(':');
          Base        base;
          std::string file;
          if (colon != std::string::npos)
            {
              base.name = trim(item.substr(0, colon));
              file      = trim(item.substr(colon + 1));
            }
          const bool good_name
            = !base.name.empty()
              && std::all_of(base.name.begin(), base.name.end(), [](char c) {
                   return std::isalnum(static_cast<unsigned char>(c))
                          || c == '-' || c == '_';
                 });
          if (!good_name || file.empty())
            throw InputError("'Study/Bases': '" + item
                             + "' is not of the form 'name: file' (a name "
                               "of letters, digits, '-' and '_', then the "
                               "path of an mca parameter file), e.g. "
                               "'steel: ../mca/friction_steel.prm'.");
          for (const Base &other : bases)
            if (other.name == base.name)
              throw InputError("'Study/Bases': the name '" + base.name
                               + "' is given twice. Name each base once.");
          base.file = file[0] == '/' ? file : join_path(directory, file);
          if (!file_exists(base.file))
            throw InputError("'Study/Bases': the file of base '" + base.name
                             + "', '" + base.file
                             + "', does not exist or is not readable "
                               "(relative paths are relative to the "
                               "directory of the study's parameter file, '"
                             + directory + "').");
          bases.push_back(base);
        }
      if (bases.empty())
        throw InputError("'Study/Bases' is empty: name at least one base "
                         "scene, e.g. 'steel: ../mca/friction_steel.prm'.");
    }


    void
    McaStudyParameters::read_factors(const std::string &text,
                                     const std::string &where)
    {
      factors.clear();
      for (const auto &[path, values] : path_assignments(text, where))
        {
          if (path == McaStudyParameters::roughness_seed_path
              || path == McaStudyParameters::inclusion_seed_path)
            throw InputError("'Study/Factors' varies '" + path
                             + "': the seeds are set by 'Study/Roughness "
                               "seeds' and 'Study/Inclusion seeds' (paired "
                               "across the bases). Use those.");
          if (path == McaStudyParameters::end_time_path)
            throw InputError("'Study/Factors' varies '" + path
                             + "': a study has one end time, 'Time/End "
                               "time'.");
          Factor f;
          f.path   = path;
          f.values = dealii::Utilities::split_string_list(values, ',');
          if (std::set<std::string>(f.values.begin(), f.values.end()).size()
                != f.values.size()
              || std::count(f.values.begin(), f.values.end(), "") > 0)
            throw InputError("'Study/Factors': the values of '" + path
                             + "' must be distinct and not empty (each is "
                               "one scene per base and seed); got '"
                             + values + "'.");
          for (const Factor &other : factors)
            if (other.path == f.path)
              throw InputError("'Study/Factors' names '" + path
                               + "' twice. List all its values once.");
          factors.push_back(f);
        }
    }


    void
    McaStudyParameters::parse_parameters(ParameterHandler  &prm,
                                         const std::string &study_file)
    {
      time_binding().parse(prm);
      const std::string directory
        = study_file.find('/') == std::string::npos
            ? std::string(".")
            : study_file.substr(0, study_file.find_last_of('/'));
      study_binding(directory).parse(prm);

      // What relates two entries.
      reference = trim(reference);
      if (reference.empty())
        reference = bases.front().name;
      if (std::none_of(bases.begin(), bases.end(), [&](const Base &b) {
            return b.name == reference;
          }))
        throw InputError("'Study/Reference base' = '" + reference
                         + "' is not one of the bases named in "
                           "'Study/Bases'. Give one of their names, or "
                           "leave it empty for the first.");
      if (roughness_seeds.empty())
        throw InputError("'Study/Roughness seeds' is empty: give at least "
                         "one seed, e.g. '1, 2, 3, 4'.");
      if (inclusion_seeds.empty())
        inclusion_seeds = roughness_seeds;
      if (inclusion_seeds.size() != roughness_seeds.size())
        throw InputError("'Study/Inclusion seeds' has "
                         + std::to_string(inclusion_seeds.size())
                         + " seeds, 'Study/Roughness seeds' "
                         + std::to_string(roughness_seeds.size())
                         + ": give one inclusion seed per roughness seed, or "
                           "none (then each equals its roughness seed).");
      // A roughness seed may come back with another inclusion seed (the
      // fibres of one surface placed anew); a pair of seeds is one scene
      // per base.
      std::set<std::pair<unsigned int, unsigned int>> pairs;
      for (unsigned int s = 0; s < roughness_seeds.size(); ++s)
        if (!pairs.insert({roughness_seeds[s], inclusion_seeds[s]}).second)
          throw InputError(
            "'Study/Roughness seeds' names the seed "
            + std::to_string(roughness_seeds[s]) + " twice with the inclusion "
            + "seed " + std::to_string(inclusion_seeds[s])
            + " ('Study/Inclusion seeds'): each pair of seeds is one pairing "
              "of the bases; list it once.");
    }
  } // namespace study
} // namespace tribodyn
