#ifndef cosmo_io_checkpoint_h
#define cosmo_io_checkpoint_h

#include <deal.II/base/parameter_handler.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

/**
 * Checkpoints and restart (README.md, "Checkpoints and restart").
 *
 * A run writes `checkpoint.cosmo` into its output directory after every
 * converged continuation step (and every finished point of a study or
 * table), atomically (a rename: a killed run leaves the last complete one).
 * It holds the application's name, the parameters it ran with (their
 * canonical text, all but the output directory) and a payload: whatever the
 * driver and the application need to go on exactly where they were (state
 * vectors, step controller, branch queue, events, the rows and file lists of
 * the output written so far), in binary so that doubles round-trip bitwise.
 * `app --resume DIR` reads DIR/parameters.prm, refuses (exit 1) a checkpoint
 * of another application or of other parameters, naming the entry, and
 * continues; the resumed run reaches the result of an uninterrupted one.
 * A run that ends (converged or failed) removes its checkpoint.
 */
namespace cosmo
{
  namespace io
  {
    using namespace dealii;

    /// The checkpoint's file name in a run directory.
    inline const std::string checkpoint_name = "checkpoint.cosmo";

    /// Binary payload being built: values appended in order.
    class CheckpointWriter
    {
    public:
      void
      put(const double v)
      {
        raw(&v, sizeof v);
      }
      void
      put(const std::uint64_t v)
      {
        raw(&v, sizeof v);
      }
      void
      put(const unsigned int v)
      {
        put(std::uint64_t(v));
      }
      void
      put(const int v)
      {
        put(double(v));
      }
      void
      put(const bool v)
      {
        put(std::uint64_t(v ? 1 : 0));
      }
      void
      put(const std::string &s)
      {
        put(std::uint64_t(s.size()));
        raw(s.data(), s.size());
      }
      template <typename Vec>
      void
      put_vector(const Vec &v)
      {
        put(std::uint64_t(v.size()));
        // One resize and a copy per value, not an append per value (a path's
        // states of 7e4 unknowns: 2 ms a checkpoint otherwise).
        const std::size_t at = data.size();
        data.resize(at + v.size() * sizeof(double));
        char *p = &data[at];
        for (const auto &x : v)
          {
            const double d = x;
            std::memcpy(p, &d, sizeof d);
            p += sizeof d;
          }
      }
      void
      put(const std::vector<std::string> &v)
      {
        put(std::uint64_t(v.size()));
        for (const auto &s : v)
          put(s);
      }
      const std::string &
      bytes() const
      {
        return data;
      }

    private:
      std::string data;
      void
      raw(const void *p, const std::size_t n)
      {
        data.append(static_cast<const char *>(p), n);
      }
    };

    /// Reads what a CheckpointWriter wrote, in the same order; std::runtime_error if it is short.
    class CheckpointReader
    {
    public:
      CheckpointReader() = default;
      explicit CheckpointReader(std::string bytes)
        : data(std::move(bytes))
      {}
      double
      get_double()
      {
        double v;
        raw(&v, sizeof v);
        return v;
      }
      std::uint64_t
      get_size()
      {
        std::uint64_t v;
        raw(&v, sizeof v);
        return v;
      }
      unsigned int
      get_unsigned()
      {
        return static_cast<unsigned int>(get_size());
      }
      int
      get_int()
      {
        return static_cast<int>(get_double());
      }
      bool
      get_bool()
      {
        return get_size() != 0;
      }
      std::string
      get_string()
      {
        const std::uint64_t n = get_size();
        check(n);
        std::string s = data.substr(position, n);
        position += n;
        return s;
      }
      std::vector<double>
      get_vector()
      {
        const std::uint64_t n = get_size();
        check(n * sizeof(double));
        std::vector<double> v(n);
        for (auto &x : v)
          x = get_double();
        return v;
      }
      template <typename Vec>
      void
      get_vector(Vec &v)
      {
        const auto x = get_vector();
        v.reinit(x.size());
        std::copy(x.begin(), x.end(), v.begin());
      }
      std::vector<std::string>
      get_strings()
      {
        const std::uint64_t n = get_size();
        check(n);
        std::vector<std::string> v(n);
        for (auto &s : v)
          s = get_string();
        return v;
      }
      bool
      at_end() const
      {
        return position == data.size();
      }

    private:
      std::string data;
      std::size_t position = 0;
      void
      check(const std::uint64_t n) const
      {
        if (n > data.size() - position)
          throw std::runtime_error("the checkpoint ends early (it is damaged or of another version)");
      }
      void
      raw(void *p, const std::size_t n)
      {
        check(n);
        std::memcpy(p, data.data() + position, n);
        position += n;
      }
    };

    /**
     * The parameters as a checkpoint records them: every entry in declaration
     * order, one `section/entry = value` line each, all but `Output directory`
     * (a run directory may be moved before it is resumed).
     */
    std::string
    checkpoint_parameters(const ParameterHandler &prm);

    /// Write `payload` with its header to directory/checkpoint.cosmo, atomically.
    void
    write_checkpoint(const std::string &     directory,
                     const std::string &     application,
                     const std::string &     parameters,
                     const CheckpointWriter &payload);

    /**
     * Read directory/checkpoint.cosmo and check that `application` with
     * `parameters` (checkpoint_parameters) wrote it; InputError (exit 1)
     * naming the directory, or the first entry that differs, if not.
     */
    CheckpointReader
    read_checkpoint(const std::string &directory,
                    const std::string &application,
                    const std::string &parameters);

    /// Remove directory/checkpoint.cosmo (a run that ended has nothing to resume).
    void
    remove_checkpoint(const std::string &directory);
  } // namespace io
} // namespace cosmo

#endif
