// The RVE-size study (Kanit et al. 2003), the same in 2D and 3D: its
// parameters, the windows, their cell problems spread over MPI rank
// groups, and the statistics. What a window is: rve_study_plane.cc (2D),
// rve_study_volume.cc (3D); tables and plot: rve_output.cc; fits:
// rve_statistics.cc.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <tribodyn/core/errors.h>
#include <tribodyn/core/number_list.h>
#include <tribodyn/core/parameter_binding.h>
#include <tribodyn/core/progress.h>
#include <tribodyn/core/selection.h>
#include <tribodyn/homogenization/rve_output.h>
#include <tribodyn/homogenization/rve_study.h>

namespace tribodyn
{
  namespace homogenization
  {
    using dealii::ParameterHandler;

    namespace
    {
      using Source = RveStudyParameters::Source;
      constexpr SelectionTable<Source, 2> source_choices{
        {{"crops", Source::crops}, {"realisations", Source::realisations}}};

      const std::string sizes_name = "RVE study/Window sizes";


      /// "140x40" -> {140, 40, 0}; "16x16x8" -> {16, 16, 8}; "32" -> {32,
      /// 0, 0} (a square or a cube: RveStudyParameters::parse_parameters()).
      std::array<unsigned int, 3>
      parse_window_size(const std::string &word)
      {
        const auto fail = [&]() {
          throw InputError(
            "Parameter '" + sizes_name + "': '" + word
            + "' is not a window size. Give each size in pixels as "
              "WIDTHxHEIGHT (e.g. 140x40), in voxels as WIDTHxHEIGHTxDEPTH "
              "(e.g. 16x16x8), or as one number for a square or a cube, the "
              "sizes separated by commas.");
        };
        std::array<unsigned int, 3> size{{0, 0, 0}};
        std::size_t                 begin = 0;
        for (unsigned int d = 0;; ++d)
          {
            const std::size_t end  = word.find_first_of("xX", begin);
            const std::string part = word.substr(begin, end - begin);
            if (d == 3 || part.empty()
                || part.find_first_not_of("0123456789") != std::string::npos
                || part.size() > 6)
              fail();
            size[d] = std::stoul(part);
            if (size[d] == 0)
              fail();
            if (end == std::string::npos)
              break;
            begin = end + 1;
          }
        return size;
      }


      /// Uniform integer in [0, n] from a 32-bit generator (multiply-shift,
      /// the same on every platform, unlike std::uniform_int_distribution).
      unsigned int
      uniform_up_to(std::mt19937 &rng, const unsigned int n)
      {
        return static_cast<unsigned int>(
          (static_cast<std::uint64_t>(rng()) * (std::uint64_t(n) + 1)) >> 32);
      }
    } // namespace


    std::string
    format_window_size(const std::array<unsigned int, 3> &size,
                       const unsigned int                 dim,
                       const std::string                 &separator)
    {
      std::string text = std::to_string(size[0]);
      for (unsigned int d = 1; d < dim; ++d)
        text += separator + std::to_string(size[d]);
      return text;
    }


    ParameterBinding
    RveStudyParameters::binding()
    {
      using dealii::Patterns::Anything;
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;
      // The defaults of the lists, written from the members: "70x20,
      // 140x40, 280x80", one number of windows when all sizes have the
      // same ("8"), "1, 6".
      std::string sizes_text, per_size_text, realisations_text;
      for (const auto &size : window_sizes)
        sizes_text += (sizes_text.empty() ? "" : ", ")
                      + format_window_size(size, size[2] > 1 ? 3 : 2);
      const bool same_per_size = std::all_of(windows_per_size.begin(),
                                             windows_per_size.end(),
                                             [this](const unsigned int n) {
                                               return n == windows_per_size[0];
                                             });
      for (const unsigned int n : windows_per_size)
        if (!same_per_size || per_size_text.empty())
          per_size_text
            += (per_size_text.empty() ? "" : ", ") + std::to_string(n);
      for (const unsigned int n : realisations)
        realisations_text
          += (realisations_text.empty() ? "" : ", ") + std::to_string(n);

      ParameterBinding b("RVE study");
      b.add("Window sizes",
            sizes_text,
            "Sizes of the windows in pixels of a 2D morphology, WIDTHxHEIGHT "
            "(along x and y), or in voxels of a volume ('Problem = "
            "volume_rve'), WIDTHxHEIGHTxDEPTH, or one number for a square or "
            "a cube, separated by commas, at least two, of increasing area or "
            "volume. Keep the aspect ratio of the cell you want to judge (the "
            "seed's cell is 280x80).",
            Anything(),
            [this](const std::string &value) {
              std::string text = value;
              std::replace(text.begin(), text.end(), ',', ' ');
              std::istringstream in(text);
              window_sizes.clear();
              for (std::string word; in >> word;)
                window_sizes.push_back(parse_window_size(word));
            });
      b.add("Windows per size",
            per_size_text,
            "Number n of windows of each size: one number for all sizes, or "
            "one per size (at least 3 each; the standard deviation of a size "
            "is known to about 1/sqrt(2 (n - 1)) relative).",
            Anything(),
            [this, path = b.path("Windows per size")](const std::string &text) {
              const std::vector<double> n = parse_number_list(text, path);
              windows_per_size.clear();
              for (const double v : n)
                {
                  check_parameter(v >= 3 && v == std::floor(v) && v < 1e6,
                                  path,
                                  "'" + format_number(v)
                                    + "' is not a whole number of at least 3 "
                                      "(a variance from fewer windows is too "
                                      "uncertain to fit).");
                  windows_per_size.push_back(static_cast<unsigned int>(v));
                }
            });
      b.add("Source",
            source,
            "'crops': windows cut at uniformly random positions from the "
            "morphology of the subsection 'Morphology' (with 'random "
            "vertical', a new realisation of it for every window, seed "
            "'Morphology/Seed' + window number, so that windows are "
            "independent; with an image, a grid file or a laminate, the one "
            "map). 'realisations': the generator ('random vertical') run at "
            "each window's size, one seed per window (pixel size = "
            "'Morphology/Width' / 'Pixels in x'); heterogeneities then never "
            "cut the window's edges, as in the seed's cells.",
            source_choices);
      b.add("Seed",
            random_seed,
            "Seed of the random window positions ('crops').",
            Integer(0));
      b.add("Relative error",
            relative_error,
            "Relative error eps_rel of the mean for which the RVE size is "
            "reported, in (0, 1): the mean of n windows of that size is within "
            "eps_rel of the mean with ~95 % confidence (two standard errors).",
            Double());
      b.add("Realisations",
            realisations_text,
            "Numbers n of realisations averaged, for which the RVE size "
            "V(eps_rel, n) is reported (the seed averages six morphologies).",
            Anything(),
            [this, path = b.path("Realisations")](const std::string &text) {
              realisations.clear();
              for (const double v : parse_number_list(text, path))
                {
                  check_parameter(v >= 1 && v == std::floor(v) && v < 1e9,
                                  path,
                                  "'" + format_number(v)
                                    + "' is not a whole number of at least "
                                      "1.");
                  realisations.push_back(static_cast<unsigned int>(v));
                }
            });
      b.add("Ranks per window",
            ranks_per_window,
            "MPI ranks that solve one window together. The ranks form n_ranks "
            "/ (Ranks per window) groups; windows go round-robin to the "
            "groups.",
            Integer(1));
      b.add("Solve cell problems",
            solve_cell_problems,
            "false: measure only the phase fractions of the windows (no cell "
            "problems; the morphology's own integral range, e.g. to choose the "
            "window sizes before paying for cell problems).");
      b.add("Plot script",
            plot_script,
            "Python script drawing rve.png at the end: 'auto' looks for "
            "scripts/plot_rve next to the build directory (skipped when "
            "python3 or matplotlib is missing), 'none' draws nothing, or a "
            "path.");
      RveOutputRegistry::add_selection(b, "Outputs", outputs, "outputs");
      return b;
    }


    void
    RveStudyParameters::declare_parameters(ParameterHandler &prm)
    {
      RveStudyParameters().binding().declare(prm);
    }


    void
    RveStudyParameters::parse_parameters(ParameterHandler  &prm,
                                         const unsigned int dim)
    {
      const ParameterBinding b = binding();
      b.parse(prm);

      check_parameter(window_sizes.size() >= 2,
                      b.path("Window sizes"),
                      "give at least two window sizes (the variance law is "
                      "fitted over the sizes), e.g. '70x20, 140x40, "
                      "280x80'.");
      // One number is a square or a cube; otherwise dim numbers.
      for (auto &size : window_sizes)
        {
          const unsigned int given = size[2] > 0 ? 3 : size[1] > 0 ? 2 : 1;
          if (given == 1)
            size[1] = size[2] = size[0];
          check_parameter(
            given == 1 || given == dim,
            b.path("Window sizes"),
            "'" + std::to_string(size[0]) + "x" + std::to_string(size[1])
              + (given == 3 ? "x" + std::to_string(size[2]) : "") + "' has "
              + std::to_string(given) + " numbers, but the windows of "
              + (dim == 2 ? "'Problem = rve' are 2D: give "
                            "WIDTHxHEIGHT in pixels"
                          : "'Problem = volume_rve' are 3D: "
                            "give WIDTHxHEIGHTxDEPTH in voxels")
              + ", or one number for a " + (dim == 2 ? "square." : "cube."));
          if (dim == 2)
            size[2] = 1;
        }
      for (unsigned int i = 1; i < window_sizes.size(); ++i)
        check_parameter(window_elements(i) > window_elements(i - 1),
                        b.path("Window sizes"),
                        std::string("the sizes must have increasing ")
                          + (dim == 2 ? "areas" : "volumes") + ", but "
                          + format_window_size(window_sizes[i], dim)
                          + " follows "
                          + format_window_size(window_sizes[i - 1], dim)
                          + ". List them from the smallest to the largest.");
      check_parameter(!windows_per_size.empty()
                        && (windows_per_size.size() == 1
                            || windows_per_size.size() == window_sizes.size()),
                      b.path("Windows per size"),
                      "give one number for all sizes or one per size ("
                        + std::to_string(window_sizes.size())
                        + " sizes are given in '" + b.path("Window sizes")
                        + "').");
      if (windows_per_size.size() == 1)
        windows_per_size.assign(window_sizes.size(), windows_per_size[0]);
      // A range of one entry, but checked here, after the lists: the
      // refusals keep their order.
      check_parameter_range(
        b.path("Relative error"), relative_error, 0, 1, true, true);
      check_parameter(!realisations.empty(),
                      b.path("Realisations"),
                      "give at least one number of realisations, e.g. '1'.");
    }


    void
    RveStudy::declare_parameters(ParameterHandler &prm)
    {
      RveStudyParameters::declare_parameters(prm);
    }


    RveStudy::RveStudy(const RunContext &context, const unsigned int dim)
        : context(context)
        , dim(dim)
    {
    }


    std::string
    RveStudy::size_text(const unsigned int size_index) const
    {
      return format_window_size(parameters.window_sizes[size_index], dim);
    }


    void
    RveStudy::check_phases_named(const unsigned int n_phases,
                                 const std::string &what) const
    {
      const unsigned int n_named = phase_names().size();
      check_parameter(n_phases <= n_named,
                      "Materials/Names",
                      what + " has material ids up to "
                        + std::to_string(n_phases - 1) + " but only "
                        + std::to_string(n_named)
                        + " materials are named. Name one material per "
                          "phase, in the order of the material ids.");
    }


    std::vector<double>
    RveStudy::fraction_values(const std::vector<double> &fractions,
                              const unsigned int         n_phases) const
    {
      check_phases_named(n_phases, "a window");
      std::vector<double> values(phase_names().size(), 0.);
      for (unsigned int k = 0; k < fractions.size() && k < values.size(); ++k)
        values[k] = fractions[k];
      return values;
    }


    void
    RveStudy::make_first_windows(
      const std::function<void(const RveWindow &)> &make) const
    {
      for (const RveWindow &w : windows)
        if (w.index == 0)
          try
            {
              make(w);
            }
          catch (const InputError &e)
            {
              throw InputError("Parameter '" + sizes_name
                               + "': the generator cannot make a window of "
                               + size_text(w.size_index)
                               + (dim == 2 ? " pixels" : " voxels")
                               + " ('Source = realisations'): " + e.what()
                               + " Use larger windows, or 'Source = crops'.");
            }
    }


    void
    RveStudy::plan_windows(const std::uint64_t morphology_seed)
    {
      for (const auto &s : parameters.window_sizes)
        for (unsigned int d = 0; d < dim; ++d)
          check_parameter(
            parameters.source == Source::realisations || s[d] <= map_size[d],
            sizes_name,
            "the window " + format_window_size(s, dim)
              + " is larger than the morphology it is cut from ("
              + format_window_size(map_size, dim)
              + (dim == 2 ? " pixels). Use smaller windows, or a larger map "
                            "('Morphology/Pixels in x', 'Pixels in y' with "
                            "'Width', 'Height' in proportion, or a larger "
                            "image)."
                          : " voxels). Use smaller windows, or a larger "
                            "volume ('Morphology/Voxels in x', 'Voxels in "
                            "y', 'Voxels in z', or a larger image stack or "
                            "raw file)."));
      // Positions drawn in window order from one generator: the same list
      // on every rank and for any number of ranks.
      std::mt19937 rng(parameters.random_seed);
      windows.clear();
      for (unsigned int s = 0; s < parameters.window_sizes.size(); ++s)
        for (unsigned int k = 0; k < parameters.windows_per_size[s]; ++k)
          {
            RveWindow w;
            w.size_index      = s;
            w.index           = k;
            w.global_index    = windows.size();
            w.morphology_seed = morphology_seed + (random ? w.global_index : 0);
            if (parameters.source == Source::crops)
              for (unsigned int d = 0; d < dim; ++d)
                w.first[d]
                  = uniform_up_to(rng,
                                  map_size[d] - parameters.window_sizes[s][d]);
            windows.push_back(w);
          }
    }


    const std::vector<BoundaryCondition> &
    RveStudy::boundary_conditions() const
    {
      static const std::vector<BoundaryCondition> none;
      return parameters.solve_cell_problems ? cell_boundary_conditions() : none;
    }


    std::vector<std::pair<std::string, std::string>>
    RveStudy::value_names() const
    {
      std::vector<std::pair<std::string, std::string>> names;
      for (const std::string &phase : phase_names())
        names.emplace_back("fraction_" + phase, "none");
      for (const BoundaryCondition bc : boundary_conditions())
        for (const std::string &c : constant_names())
          names.emplace_back(c, to_string(bc));
      return names;
    }


    std::vector<double>
    RveStudy::point_variances(const std::vector<double> &fractions) const
    {
      std::vector<double> v;
      for (unsigned int k = 0; k < fractions.size(); ++k)
        v.push_back(fractions[k] * (1 - fractions[k]));
      const auto constants = phase_constants();
      for (unsigned int b = 0; b < boundary_conditions().size(); ++b)
        for (const auto &values : constants)
          v.push_back(rve::point_variance(fractions, values));
      return v;
    }


    void
    RveStudy::run()
    {
      const auto         start = std::chrono::steady_clock::now();
      const MPI_Comm     world = context.mpi_communicator;
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(world);
      const unsigned int n_ranks
        = dealii::Utilities::MPI::n_mpi_processes(world);
      dealii::ConditionalOStream pcout(std::cout, rank == 0);
      const unsigned int         n_groups
        = std::max(1u, n_ranks / parameters.ranks_per_window);
      const unsigned int color
        = std::min(rank / parameters.ranks_per_window, n_groups - 1);
      MPI_Comm group;
      MPI_Comm_split(world, color, rank, &group);
      const bool group_root
        = dealii::Utilities::MPI::this_mpi_process(group) == 0;

      const auto         names    = value_names();
      const unsigned int n_values = names.size();
      pcout << "RVE study: " << windows.size() << " windows of "
            << parameters.window_sizes.size() << " sizes ("
            << (parameters.source == Source::crops ? "crops" : "realisations")
            << "), " << boundary_conditions().size()
            << " boundary condition(s), on " << n_groups << " group(s) of ranks"
            << std::endl;
      context.claim_output();

      // Windows round-robin over the groups; rank 0 (root of group 0)
      // reports its group's progress, with an ETA from the pixels done
      // (the cost of a window grows with its pixels, slightly faster).
      const auto pixels = [&](const RveWindow &w) {
        return parameters.window_elements(w.size_index);
      };
      unsigned int n_mine = 0, n_done = 0;
      double       pixels_mine = 0, pixels_done = 0;
      for (unsigned int i = 0; i < windows.size(); ++i)
        if (i % n_groups == color)
          {
            ++n_mine;
            pixels_mine += pixels(windows[i]);
          }
      // The cell problems' timings, summed over the windows of each group;
      // rank 0 prints its group's at the end.
      auto timer = std::make_unique<dealii::TimerOutput>(
        group,
        pcout,
        dealii::TimerOutput::summary,
        dealii::TimerOutput::wall_times);
      std::vector<double> local(windows.size() * n_values, 0.);
      const auto          t0          = std::chrono::steady_clock::now();
      double              last_report = -1e300;
      std::string         failure;
      bool                input_error = false;
      for (unsigned int i = 0; i < windows.size(); ++i)
        {
          if (i % n_groups != color || !failure.empty())
            continue;
          const RveWindow    &w = windows[i];
          std::vector<double> values;
          // A window that fails (CG without convergence, bad input) stops
          // its group; the others finish their windows, then every rank
          // throws together instead of waiting for the group forever.
          try
            {
              values = measure(w, group, *timer);
            }
          catch (const InputError &e)
            {
              failure     = "Window " + std::to_string(i + 1) + ": " + e.what();
              input_error = true;
              continue;
            }
          catch (const std::exception &e)
            {
              failure = "Window " + std::to_string(i + 1) + ": " + e.what();
              continue;
            }
          if (group_root)
            std::copy(values.begin(), values.end(), &local[i * n_values]);
          ++n_done;
          pixels_done += pixels(w);
          const double elapsed = std::chrono::duration<double>(
                                   std::chrono::steady_clock::now() - t0)
                                   .count();
          if (rank == 0
              && (elapsed - last_report >= context.progress_interval
                  || n_done == n_mine || n_done == 1))
            {
              last_report = elapsed;
              std::ostringstream line;
              line << "Window " << i + 1 << "/" << windows.size() << " ("
                   << size_text(w.size_index) << (dim == 2 ? " px" : " voxels")
                   << ", map seed " << w.morphology_seed << ")";
              const auto         phases   = phase_names();
              const unsigned int n_phases = phases.size();
              line << "  fraction_" << phases.back() << " = " << std::fixed
                   << std::setprecision(4) << values[n_phases - 1];
              const unsigned int n_constants = constant_names().size();
              for (unsigned int b = 0; b < boundary_conditions().size(); ++b)
                line << "  " << names[n_phases + n_constants * b].second << " "
                     << constant_names()[0] << " = " << std::fixed
                     << std::setprecision(3)
                     << values[n_phases + n_constants * b] / 1e9 << " GPa";
              if (n_done < n_mine)
                line << "  ETA "
                     << format_duration(elapsed * (pixels_mine - pixels_done)
                                        / pixels_done);
              line << "  elapsed " << format_duration(elapsed);
              std::cout << line.str() << std::endl;
            }
        }
      // Free the timer first when a window failed: its destructor talks
      // to the group, which it must not do while an exception unwinds.
      if (dealii::Utilities::MPI::max(failure.empty() ? 0u : 1u, world) > 0)
        {
          timer->disable_output();
          timer.reset();
        }
      refuse_collectively(world, input_error, failure);
      throw_collectively(world, !failure.empty(), failure);
      std::vector<double> all(local.size());
      MPI_Allreduce(
        local.data(), all.data(), local.size(), MPI_DOUBLE, MPI_SUM, world);

      // Samples per (size, value); mean fractions over all windows for the
      // point variances.
      const unsigned int  n_sizes  = parameters.window_sizes.size();
      const unsigned int  n_phases = phase_names().size();
      std::vector<double> mean_fractions(n_phases, 0.);
      for (unsigned int i = 0; i < windows.size(); ++i)
        for (unsigned int k = 0; k < n_phases; ++k)
          mean_fractions[k] += all[i * n_values + k] / windows.size();
      const std::vector<double> D2 = point_variances(mean_fractions);

      std::vector<RveSample> samples;
      std::vector<RveFit>    fits;
      // (the areas of 2D windows, the volumes of 3D ones: the fits take
      // either)
      std::vector<double> measures;
      for (const auto &s : parameters.window_sizes)
        measures.push_back(s[0] * element_size[0] * s[1] * element_size[1]
                           * s[2] * element_size[2]);
      for (unsigned int v = 0; v < n_values; ++v)
        {
          std::vector<rve::SampleStatistics> stats;
          for (unsigned int s = 0; s < n_sizes; ++s)
            {
              std::vector<double> x;
              for (unsigned int i = 0; i < windows.size(); ++i)
                if (windows[i].size_index == s)
                  x.push_back(all[i * n_values + v]);
              stats.push_back(rve::sample_statistics(x));
            }
          const double largest = stats.back().mean;
          for (unsigned int s = 0; s < n_sizes; ++s)
            {
              RveSample r;
              r.size_index         = s;
              r.property           = names[v].first;
              r.boundary_condition = names[v].second;
              r.statistics         = stats[s];
              r.bias = largest != 0 ? stats[s].mean / largest - 1 : 0;
              samples.push_back(r);
            }
          RveFit f;
          f.property           = names[v].first;
          f.boundary_condition = names[v].second;
          f.fit                = rve::fit_variance(measures, stats, D2[v]);
          f.mean               = largest;
          for (const unsigned int n : parameters.realisations)
            f.rve_measure.push_back(
              rve::rve_area(f.fit, largest, parameters.relative_error, n));
          fits.push_back(f);
        }

      const double wall_time = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - start)
                                 .count();
      // (the voxel grid does not time itself: no empty table)
      if (timer->get_summary_data(dealii::TimerOutput::total_wall_time).empty())
        timer->disable_output();
      if (rank == 0)
        write_results(samples, fits, n_groups, wall_time);
      MPI_Barrier(world);
      timer.reset(); // collective over the group: before freeing it
      MPI_Comm_free(&group);
    }
  } // namespace homogenization
} // namespace tribodyn
