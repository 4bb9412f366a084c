#include <cosmo/assembly/reduced_rod_records.h>
#include <cosmo/kinematics/helix.h>

#include <stdexcept>

namespace cosmo
{
  namespace assembly
  {
    void
    ReducedRodRecords::record_event(const Event &                e,
                                    const std::array<double, 6> &strains,
                                    const Vector<double> &       U,
                                    const Vector<double> *       mode)
    {
      located_events.push_back(e);
      strains_at_events.push_back(strains);
      solvers::EventRecord r;
      r.event = e;
      r.state.assign(U.begin(), U.end());
      if (mode)
        r.mode.assign(mode->begin(), mode->end());
      records.push_back(std::move(r));
    }

    void
    ReducedRodRecords::save_records(io::CheckpointWriter &w) const
    {
      w.put(std::uint64_t(visited.size()));
      for (const auto &p : visited)
        {
          w.put(p.t);
          w.put(p.branch);
          w.put(p.energy);
          w.put(p.n_negative);
          w.put_vector(p.strains);
          w.put_vector(p.resultants);
        }
      w.put(std::uint64_t(records.size()));
      for (unsigned int k = 0; k < records.size(); ++k)
        {
          records[k].save(w);
          w.put_vector(strains_at_events[k]);
        }
    }

    void
    ReducedRodRecords::load_records(io::CheckpointReader &r)
    {
      auto get6 = [&r](std::array<double, 6> &a) {
        const auto v = r.get_vector();
        if (v.size() != 6)
          throw std::runtime_error("the checkpoint is damaged (6 strains expected)");
        std::copy(v.begin(), v.end(), a.begin());
      };
      visited.resize(r.get_size());
      for (auto &p : visited)
        {
          p.t          = r.get_double();
          p.branch     = r.get_unsigned();
          p.energy     = r.get_double();
          p.n_negative = r.get_int();
          get6(p.strains);
          get6(p.resultants);
        }
      records.resize(r.get_size());
      strains_at_events.resize(records.size());
      located_events.clear();
      for (unsigned int k = 0; k < records.size(); ++k)
        {
          records[k].load(r);
          get6(strains_at_events[k]);
          located_events.push_back(records[k].event);
        }
    }

    void
    add_state_to_summary(io::JSON &                                           j,
                         const ReducedRodState &                              s,
                         const RodStrainControl &                             control,
                         const ReducedRodRecords &                            records,
                         const std::function<void(unsigned int, io::JSON &)> &event_extra)
    {
      using io::JSON;
      j["energy"] = s.energy;
      for (unsigned int k = 0; k < 6; ++k)
        {
          j["strains"][kinematics::strain_names[k]]       = s.strains[k];
          j["resultants"][kinematics::resultant_names[k]] = s.resultants[k];
        }
      j["multipliers"] = JSON::array(std::vector<double>(s.multipliers.begin(), s.multipliers.end()));
      // Resultant control: what the free strains' resultants are held at (t nbar).
      if (control.holds_resultants())
        {
          const auto held = control.resultants_at(s.t);
          for (unsigned int k = 0; k < 6; ++k)
            if (control.free_strains()[k])
              j["held_resultants"][kinematics::resultant_names[k]] = held[k];
        }
      JSON K           = JSON::array();
      for (unsigned int a = 0; a < s.stiffness.m(); ++a)
        {
          std::vector<double> row(6);
          for (unsigned int b = 0; b < 6; ++b)
            row[b] = s.stiffness(a, b);
          K.push_back(JSON::array(row));
        }
      j["stiffness"]                           = K;
      j["stiffness_order"]                     = "nu1, nu2, nu3, kappa1, kappa2, kappa3";
      j["stability"]["n_negative_eigenvalues"] = s.n_negative;
      JSON ev                                  = JSON::array();
      for (unsigned int k = 0; k < records.events().size(); ++k)
        {
          const auto &e          = records.events()[k];
          JSON        x          = JSON::object();
          x["kind"]              = e.name();
          x["t"]                 = e.lambda; // the load parameter, as in steps.csv (all applications)
          x["branch"]            = e.branch;
          x["n_negative_before"] = e.n_negative_before;
          x["n_negative_after"]  = e.n_negative_after;
          x["eigenvalue"]        = e.eigenvalue;
          solvers::add_location_to_json(e, x);
          for (unsigned int c = 0; c < 6; ++c)
            x["strains"][kinematics::strain_names[c]] = records.event_strains()[k][c];
          if (event_extra)
            event_extra(k, x);
          ev.push_back(x);
        }
      j["events"] = ev;
    }
  } // namespace assembly
} // namespace cosmo
