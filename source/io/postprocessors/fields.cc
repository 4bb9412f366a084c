// The postprocessor 'fields': the application's fields as VTU files, with
// their ParaView collections.
#include <deal.II/base/utilities.h>

#include <cosmo/io/output.h>
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
        prm.declare_entry("Steps between outputs", "1", Patterns::Integer(0),
                          "1: the fields of every converged state; n: of every n-th step "
                          "and of the last state of the path (or of each branch); 0: of the "
                          "last state only. A path that ends before its target (the run "
                          "fails, exit 2) still writes its last converged state.");
      }
      void
      parse_parameters(ParameterHandler &prm) override
      {
        interval = prm.get_integer("Steps between outputs");
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
        last_written = s.final || (interval != 0 && s.step % interval == 0);
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
      unsigned int                                            interval = 1;
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
