#ifndef cosmo_base_plugins_h
#define cosmo_base_plugins_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

/**
 * Extension by registration (as ASPECT's plugins): an implementation of an
 * interface (a bulk growth law, ...) registers itself by name from its own
 * file with COSMO_REGISTER_PLUGIN, and the name then appears in the
 * parameter file's Patterns::Selection, in the entry's documentation (from
 * the registered description) and in the user guide's parameter tables,
 * with no enum or if-chain to edit (doc/cookbook.md).
 *
 * The registry of an interface is one map per process: Registry<I>::entries()
 * is explicitly instantiated in the library next to the interface
 * (extern template below it), so that registrations from the library and
 * from an executable's own files (a test, a user's extension) land in the
 * same map. Registration runs during static initialization, before main()
 * declares any parameter.
 */
namespace cosmo
{
  namespace plugins
  {
    using namespace dealii;

    /// Registrations refused so far (a name registered twice), in order;
    /// io::load_shared_libraries() reports those of a library it loads.
    std::vector<std::string> &
    registration_errors();

    template <class Interface>
    class Registry
    {
    public:
      struct Entry
      {
        std::string name;
        /// One sentence: what it is (the documentation of the selection).
        std::string description;
        /// Its own entries, in the section the selection is declared in
        /// (may be empty).
        std::function<void(ParameterHandler &)> declare_parameters;
        std::function<std::unique_ptr<Interface>()> create;
      };

      /**
       * Registers an implementation. A name registered twice (a user's
       * library loaded at run time that repeats a name) keeps the first and
       * is recorded in registration_errors(): registration runs in static
       * initialization, where an exception would end the process unexplained.
       */
      static bool
      add(Entry e)
      {
        auto &m = entries();
        if (m.find(e.name) != m.end())
          {
            registration_errors().push_back("'" + e.name + "' is registered twice");
            return false;
          }
        const std::string name = e.name;
        m.emplace(name, std::move(e));
        return true;
      }

      /// A new instance of the implementation registered as `name`.
      static std::unique_ptr<Interface>
      create(const std::string &name)
      {
        const auto it = entries().find(name);
        AssertThrow(it != entries().end(),
                    ExcMessage("nothing is registered as '" + name + "' (registered: " +
                               names() + ")"));
        return it->second.create();
      }

      /// "a|b|c", for Patterns::Selection (sorted by name).
      static std::string
      names()
      {
        std::string s;
        for (const auto &e : entries())
          s += (s.empty() ? "" : "|") + e.first;
        return s;
      }

      /// "a: description. b: description.", for the selection's documentation.
      static std::string
      documentation()
      {
        std::string s;
        for (const auto &e : entries())
          s += (s.empty() ? "" : " ") + e.first + ": " + e.second.description;
        return s;
      }

      /// Declares every implementation's own entries.
      static void
      declare_parameters(ParameterHandler &prm)
      {
        for (const auto &e : entries())
          if (e.second.declare_parameters)
            e.second.declare_parameters(prm);
      }

      static std::map<std::string, Entry> &
      entries();
    };

    template <class Interface>
    std::map<std::string, typename Registry<Interface>::Entry> &
    Registry<Interface>::entries()
    {
      static std::map<std::string, Entry> m;
      return m;
    }
  } // namespace plugins
} // namespace cosmo

/**
 * Registers Class (default-constructible, derived from Interface, with a
 * static declare_parameters(ParameterHandler &)) under `name`. At namespace
 * scope in the implementation's file.
 */
#define COSMO_REGISTER_PLUGIN(Interface, Class, name, description)                              \
  namespace                                                                                    \
  {                                                                                            \
    const bool cosmo_plugin_registered_##Class = ::cosmo::plugins::Registry<Interface>::add( \
      {name, description, &Class::declare_parameters, []() -> std::unique_ptr<Interface> {    \
         return std::make_unique<Class>();                                                     \
       }});                                                                                    \
  }

#endif
