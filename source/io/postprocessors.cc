#include <cosmo/io/parameters.h>
#include <cosmo/io/postprocessors.h>

#include <limits>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<io::Postprocessor>;
  }

  namespace io
  {
    double
    PostprocessedState::quantity(const std::string &name) const
    {
      for (const auto &q : quantities)
        if (q.first == name)
          return q.second;
      return std::numeric_limits<double>::quiet_NaN();
    }

    void
    Postprocessors::declare_parameters(ParameterHandler &prm)
    {
      using R = plugins::Registry<Postprocessor>;
      prm.enter_subsection("Postprocess");
      prm.declare_entry("List of postprocessors", "steps table, fields",
                        Patterns::MultipleSelection(R::names()),
                        "Postprocessors called at every converged state and located event, "
                        "separated by ','; each has its entries in its own subsection. "
                        "'steps table' and 'fields' are the run's steps.csv and VTU files: "
                        "leave one out to have none. " +
                          R::documentation());
      for (const auto &e : R::entries())
        if (e.second.declare_parameters)
          {
            prm.enter_subsection(e.first);
            e.second.declare_parameters(prm);
            prm.leave_subsection();
          }
      prm.leave_subsection();
    }

    void
    Postprocessors::parse_parameters(ParameterHandler &prm)
    {
      selected.clear();
      prm.enter_subsection("Postprocess");
      const std::string list = prm.get("List of postprocessors");
      for (const std::string &name : Utilities::split_string_list(list, ','))
        {
          for (const auto &s : selected)
            if (s.first == name)
              {
                prm.leave_subsection();
                throw InputError("Postprocess", "List of postprocessors", list,
                                 "'" + name + "' is listed twice");
              }
          auto p = plugins::Registry<Postprocessor>::create(name);
          prm.enter_subsection(name);
          try
            {
              p->parse_parameters(prm);
            }
          catch (...)
            {
              prm.leave_subsection();
              prm.leave_subsection();
              throw;
            }
          prm.leave_subsection();
          selected.emplace_back(name, std::move(p));
        }
      prm.leave_subsection();
    }

    void
    Postprocessors::execute(const PostprocessedState &state)
    {
      for (auto &s : selected)
        if (state.kind == PostprocessedState::Kind::path_end)
          s.second->path_ended(state);
        else
          s.second->execute(state);
    }

    void
    Postprocessors::finish(const std::string &output_directory)
    {
      for (auto &s : selected)
        s.second->finish(output_directory);
    }

    void
    Postprocessors::save(CheckpointWriter &w) const
    {
      w.put(std::uint64_t(selected.size()));
      for (const auto &s : selected)
        {
          w.put(s.first);
          s.second->save(w);
        }
    }

    void
    Postprocessors::load(CheckpointReader &r, const std::string &output_directory)
    {
      // The checkpoint holds the run's parameters, so the same list.
      if (r.get_size() != selected.size())
        throw std::runtime_error("the checkpoint's postprocessors differ from this run's");
      for (auto &s : selected)
        {
          if (r.get_string() != s.first)
            throw std::runtime_error("the checkpoint's postprocessors differ from this run's");
          s.second->load(r, output_directory);
        }
    }
  } // namespace io
} // namespace cosmo
