// The postprocessor 'fields': the application's fields as VTU files, with
// their ParaView collections.
#include <deal.II/base/utilities.h>

#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/postprocessors.h>

#include <algorithm>
#include <map>
#include <memory>

namespace cosmo
{
  namespace io
  {
    /**
     * The fields of converged states (io::StateSource::write_fields: one
     * file per kind, e.g. plate-0003.vtu and rim-0003.vtu) and, per kind,
     * the collections kind.pvd (path order) and kind-branch-K.pvd (time =
     * t; io::PathCollections). The file tag is the step number, or the next
     * free one should a step be reported twice (a continued critical point
     * after its path), so that no file is written over. At each located
     * event, the state and mode there (io::StateSource::write_event_fields).
     */
    class Fields : public Postprocessor
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Steps between outputs", "auto", Patterns::Anything(),
                          "auto: the fields of every converged state, except in a run that "
                          "stops at its first event (Arclength continuation/Stop at first "
                          "event): there only the event's state and mode (and the last state, "
                          "should the path end without one), since the states on the way are "
                          "of no use and their files cost more than the threshold's "
                          "computation on small problems. 1: every converged state; n: every "
                          "n-th step and the last state of the path (or of each branch); 0: "
                          "the last state only. Events are always written. A path that ends "
                          "before its target (the run fails, exit 2) still writes its last "
                          "converged state.");
      }
      void
      parse_parameters(ParameterHandler &prm) override
      {
        const std::string value = Utilities::trim(prm.get("Steps between outputs"));
        if (value == "auto")
          {
            interval = automatic;
            return;
          }
        // (a whole number: digits only, at most 9 of them)
        if (value.empty() || value.size() > 9 ||
            value.find_first_not_of("0123456789") != std::string::npos)
          throw InputError("Postprocess/fields", "Steps between outputs", value,
                           "auto, or a whole number >= 0 (0: the last state only)");
        interval = std::stoi(value);
      }
      void
      execute(const PostprocessedState &s) override
      {
        if (s.source == nullptr)
          return;
        if (s.kind == PostprocessedState::Kind::located_event)
          {
            // Every event's state and mode, whatever 'Steps between outputs'.
            ++events;
            if (s.unknowns != nullptr)
              s.source->write_event_fields(Utilities::int_to_string(events, 2), *s.unknowns, s.mode);
            return;
          }
        // auto: every state, but none on the way to a first event
        const int every = interval != automatic ? interval : (s.toward_first_event ? 0 : 1);
        last_written    = s.final || (every != 0 && s.step % every == 0);
        if (last_written)
          write(s);
      }
      /// A path that fails still leaves its last state (skipped by 'Steps
      /// between outputs'): the application's state is still that one.
      void
      path_ended(const PostprocessedState &s) override
      {
        if (!last_written && s.source != nullptr)
          write(s);
        last_written = true;
      }
      void
      save(CheckpointWriter &w) const override
      {
        w.put(written);
        w.put(last_written);
        w.put(next_tag);
        w.put(events);
        w.put(std::uint64_t(collections.size()));
        for (const auto &[kind, c] : collections)
          {
            w.put(kind);
            c->save(w);
          }
      }
      void
      load(CheckpointReader &r, const std::string &output_directory) override
      {
        written      = r.get_bool();
        last_written = r.get_bool();
        next_tag     = r.get_unsigned();
        events       = r.get_unsigned();
        collections.clear();
        for (std::uint64_t k = 0, n = r.get_size(); k < n; ++k)
          {
            const std::string kind = r.get_string();
            collection(output_directory, kind).load(r);
          }
      }

    private:
      void
      write(const PostprocessedState &s)
      {
        const unsigned int tag = written ? std::max(s.step, next_tag) : s.step;
        for (const auto &[kind, file] : s.source->write_fields(Utilities::int_to_string(tag, 4)))
          collection(s.output_directory, kind).add(s.step, s.branch, s.t, file);
        next_tag = tag + 1;
        written  = true;
      }
      PathCollections &
      collection(const std::string &directory, const std::string &kind)
      {
        auto &c = collections[kind];
        if (!c)
          c = std::make_unique<PathCollections>(directory, kind);
        return *c;
      }
      static constexpr int                                    automatic = -1;
      int                                                     interval  = automatic;
      bool                                                    written  = false;
      /// Whether the last converged state's fields were written.
      bool                                                    last_written = true;
      unsigned int                                            next_tag = 0;
      unsigned int                                            events   = 0; ///< located so far
      std::map<std::string, std::unique_ptr<PathCollections>> collections;
    };

    COSMO_REGISTER_PLUGIN(Postprocessor,
                          Fields,
                          "fields",
                          "The application's fields as VTU files (.pvtu on a distributed mesh) "
                          "with their ParaView collections: KIND.pvd in path order and "
                          "KIND-branch-K.pvd in the load parameter.")
  } // namespace io
} // namespace cosmo
