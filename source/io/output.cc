#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/run_directory.h>

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace cosmo
{
  namespace io
  {
    void
    write_file_atomically(const std::string &                        path,
                          const std::function<void(std::ostream &)> &writer)
    {
      // The process id in the temporary name: two processes writing the
      // same file (two runs into one directory, refused by the lock, or a
      // file outside any run directory) cannot take each other's.
      const std::string tmp = path + ".tmp." + std::to_string(::getpid());
      std::error_code ec;
      try
        {
          std::ofstream out(tmp);
          if (!out)
            throw std::runtime_error("cannot write the file '" + tmp + "'");
          writer(out);
          out.flush();
          if (!out)
            throw std::runtime_error("writing '" + tmp + "' failed (disk full?)");
        }
      catch (...)
        {
          std::filesystem::remove(tmp, ec); // no partial file left behind
          throw;
        }
      std::filesystem::rename(tmp, path, ec);
      if (ec)
        {
          std::filesystem::remove(tmp, ec);
          throw std::runtime_error("cannot rename '" + tmp + "' to '" + path + "': " + ec.message());
        }
      record_output_file(path);
    }

    void
    create_directory(const std::string &path)
    {
      // A control character (a NUL byte cuts the name the system sees, and
      // every message that prints it) is no part of a directory name.
      for (std::size_t i = 0; i < path.size(); ++i)
        if (static_cast<unsigned char>(path[i]) < 0x20 || path[i] == 0x7f)
          {
            std::string shown;
            for (const char c : path)
              shown += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
            std::ostringstream code;
            code << "0x" << std::hex << std::setw(2) << std::setfill('0')
                 << static_cast<int>(static_cast<unsigned char>(path[i]));
            throw InputError("Output", "Output directory", shown,
                             "a path without control characters (character " +
                               std::to_string(i + 1) + " is " + code.str() + ", shown as '?')");
          }
      std::error_code ec;
      std::filesystem::create_directories(path, ec);
      if (ec || !std::filesystem::is_directory(path))
        throw std::runtime_error("cannot create the output directory '" + path + "'" +
                                 (ec ? ": " + ec.message() : ""));
    }

    std::string
    format_significant(const double v, const int precision)
    {
      std::ostringstream s;
      s << std::setprecision(precision) << v;
      return s.str();
    }

    std::string
    format_number(const double v)
    {
      if (std::isnan(v))
        return "nan";
      if (std::isinf(v))
        return v > 0 ? "inf" : "-inf";
      std::ostringstream s;
      s << std::setprecision(std::numeric_limits<double>::max_digits10) << v;
      // Shorter representation when it round-trips.
      for (int p = 6; p < std::numeric_limits<double>::max_digits10; ++p)
        {
          std::ostringstream t;
          t << std::setprecision(p) << v;
          // (strtod, not stod: stod throws on a subnormal number)
          if (std::strtod(t.str().c_str(), nullptr) == v)
            return t.str();
        }
      return s.str();
    }

    void
    CSVTable::add_column(const std::string &name, const std::string &unit)
    {
      columns.push_back(unit.empty() ? name : name + " [" + unit + "]");
      names.push_back(name);
    }

    std::vector<std::pair<std::string, double>>
    CSVTable::last_row() const
    {
      std::vector<std::pair<std::string, double>> r;
      if (!rows.empty())
        for (unsigned int k = 0; k < names.size(); ++k)
          r.emplace_back(names[k], rows.back()[k]);
      return r;
    }

    void
    CSVTable::add_row(const std::vector<double> &values)
    {
      if (values.size() != columns.size())
        throw std::logic_error("CSV row of " + std::to_string(values.size()) +
                               " values for " + std::to_string(columns.size()) + " columns");
      rows.push_back(values);
    }

    void
    CSVTable::write(const std::string &path) const
    {
      write_file_atomically(path, [&](std::ostream &out) {
        for (unsigned int c = 0; c < columns.size(); ++c)
          out << (c ? "," : "") << columns[c];
        out << "\n";
        for (const auto &row : rows)
          {
            for (unsigned int c = 0; c < row.size(); ++c)
              out << (c ? "," : "") << format_number(row[c]);
            out << "\n";
          }
      });
    }

    JSON::JSON()
      : type(Type::null)
    {}
    JSON::JSON(const double v)
      : type(Type::number)
      , number(v)
    {}
    JSON::JSON(const int v)
      : type(Type::number)
      , number(v)
    {}
    JSON::JSON(const unsigned int v)
      : type(Type::number)
      , number(v)
    {}
    JSON::JSON(const bool v)
      : type(Type::boolean)
      , boolean(v)
    {}
    JSON::JSON(const char *v)
      : type(Type::string)
      , text(v)
    {}
    JSON::JSON(const std::string &v)
      : type(Type::string)
      , text(v)
    {}

    JSON
    JSON::array()
    {
      JSON j;
      j.type = Type::array_t;
      return j;
    }

    JSON
    JSON::object()
    {
      JSON j;
      j.type = Type::object_t;
      return j;
    }

    JSON
    JSON::array(const std::vector<double> &v)
    {
      JSON j = array();
      for (const double x : v)
        j.push_back(JSON(x));
      return j;
    }

    JSON &JSON::operator[](const std::string &key)
    {
      if (type == Type::null)
        type = Type::object_t;
      if (type != Type::object_t)
        throw std::logic_error("JSON: not an object");
      for (auto &m : members)
        if (m.first == key)
          return *m.second;
      members.emplace_back(key, std::make_shared<JSON>());
      return *members.back().second;
    }

    void
    JSON::push_back(const JSON &v)
    {
      if (type == Type::null)
        type = Type::array_t;
      if (type != Type::array_t)
        throw std::logic_error("JSON: not an array");
      items.push_back(v);
    }

    namespace
    {
      void
      print_string(std::ostream &out, const std::string &s)
      {
        out << '"';
        for (const char c : s)
          switch (c)
            {
              case '"':
                out << "\\\"";
                break;
              case '\\':
                out << "\\\\";
                break;
              case '\n':
                out << "\\n";
                break;
              case '\t':
                out << "\\t";
                break;
              default:
                if (static_cast<unsigned char>(c) < 0x20)
                  {
                    char buf[8];
                    std::snprintf(buf, sizeof(buf), "\\u%04x", c);
                    out << buf;
                  }
                else
                  out << c;
            }
        out << '"';
      }
    } // namespace

    void
    JSON::print(std::ostream &out, const unsigned int indent) const
    {
      const std::string pad(indent + 2, ' '), pad_end(indent, ' ');
      switch (type)
        {
          case Type::null:
            out << "null";
            break;
          case Type::number:
            // JSON has no inf/nan: null stands for "not a number here".
            if (std::isfinite(number))
              out << format_number(number);
            else
              out << "null";
            break;
          case Type::string:
            print_string(out, text);
            break;
          case Type::boolean:
            out << (boolean ? "true" : "false");
            break;
          case Type::array_t:
            {
              bool flat = true;
              for (const auto &i : items)
                flat = flat && (i.type == Type::number || i.type == Type::string ||
                                i.type == Type::boolean || i.type == Type::null);
              out << "[";
              for (unsigned int k = 0; k < items.size(); ++k)
                {
                  out << (k ? "," : "") << (flat ? (k ? " " : "") : "\n" + pad);
                  items[k].print(out, indent + 2);
                }
              if (!flat && !items.empty())
                out << "\n" << pad_end;
              out << "]";
              break;
            }
          case Type::object_t:
            out << "{";
            for (unsigned int k = 0; k < members.size(); ++k)
              {
                out << (k ? "," : "") << "\n" << pad;
                print_string(out, members[k].first);
                out << ": ";
                members[k].second->print(out, indent + 2);
              }
            if (!members.empty())
              out << "\n" << pad_end;
            out << "}";
            break;
        }
    }

    std::string
    JSON::str() const
    {
      std::ostringstream s;
      print(s);
      return s.str();
    }

    namespace
    {
      /// Recursive descent over a JSON text (RFC 8259; \u escapes of the
      /// basic plane are read as one byte if below 0x80, else as '?').
      class JSONParser
      {
      public:
        explicit JSONParser(const std::string &t)
          : text(t)
        {}

        JSON
        document()
        {
          JSON v = value();
          skip_space();
          if (pos != text.size())
            fail("the end of the text");
          return v;
        }

      private:
        const std::string &text;
        std::size_t        pos = 0;

        [[noreturn]] void
        fail(const std::string &expected) const
        {
          throw std::runtime_error("not JSON at character " + std::to_string(pos + 1) +
                                   ": expected " + expected);
        }
        void
        skip_space()
        {
          while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos])))
            ++pos;
        }
        bool
        take(const char c)
        {
          skip_space();
          if (pos < text.size() && text[pos] == c)
            {
              ++pos;
              return true;
            }
          return false;
        }
        bool
        take_word(const std::string &w)
        {
          if (text.compare(pos, w.size(), w) != 0)
            return false;
          pos += w.size();
          return true;
        }
        std::string
        string()
        {
          if (!take('"'))
            fail("'\"'");
          std::string out;
          while (pos < text.size() && text[pos] != '"')
            {
              char c = text[pos++];
              if (c == '\\')
                {
                  if (pos >= text.size())
                    break;
                  const char e = text[pos++];
                  switch (e)
                    {
                      case 'n':
                        c = '\n';
                        break;
                      case 't':
                        c = '\t';
                        break;
                      case 'r':
                        c = '\r';
                        break;
                      case 'b':
                        c = '\b';
                        break;
                      case 'f':
                        c = '\f';
                        break;
                      case 'u':
                        {
                          if (pos + 4 > text.size())
                            fail("four hex digits");
                          const unsigned long code = std::stoul(text.substr(pos, 4), nullptr, 16);
                          pos += 4;
                          c = code < 0x80 ? static_cast<char>(code) : '?';
                          break;
                        }
                      default:
                        c = e; // \" \\ \/
                    }
                }
              out += c;
            }
          if (pos >= text.size())
            fail("the closing '\"' of a string");
          ++pos;
          return out;
        }
        JSON
        value()
        {
          skip_space();
          if (pos >= text.size())
            fail("a value");
          const char c = text[pos];
          if (c == '{')
            {
              ++pos;
              JSON o = JSON::object();
              if (take('}'))
                return o;
              do
                {
                  const std::string key = (skip_space(), string());
                  if (!take(':'))
                    fail("':'");
                  o[key] = value();
                }
              while (take(','));
              if (!take('}'))
                fail("',' or '}'");
              return o;
            }
          if (c == '[')
            {
              ++pos;
              JSON a = JSON::array();
              if (take(']'))
                return a;
              do
                a.push_back(value());
              while (take(','));
              if (!take(']'))
                fail("',' or ']'");
              return a;
            }
          if (c == '"')
            return JSON(string());
          if (take_word("true"))
            return JSON(true);
          if (take_word("false"))
            return JSON(false);
          if (take_word("null"))
            return JSON();
          const char *begin = text.c_str() + pos;
          char *      end   = nullptr;
          const double v    = std::strtod(begin, &end);
          if (end == begin)
            fail("a value (object, array, string, number, true, false or null)");
          pos += end - begin;
          return JSON(v);
        }
      };
    } // namespace

    JSON
    JSON::parse(const std::string &text)
    {
      return JSONParser(text).document();
    }

    double
    JSON::as_number() const
    {
      if (type == Type::null)
        return std::numeric_limits<double>::quiet_NaN();
      if (type != Type::number)
        throw std::runtime_error("JSON: a number was expected");
      return number;
    }

    std::size_t
    JSON::size() const
    {
      return type == Type::array_t ? items.size() : type == Type::object_t ? members.size() : 0;
    }

    const JSON &
    JSON::at(const std::size_t k) const
    {
      if (type != Type::array_t || k >= items.size())
        throw std::runtime_error("JSON: no item " + std::to_string(k) + " in this value");
      return items[k];
    }

    const JSON *
    JSON::find(const std::string &key) const
    {
      if (type != Type::object_t)
        return nullptr;
      for (const auto &m : members)
        if (m.first == key)
          return m.second.get();
      return nullptr;
    }

    RunLog::RunLog(const std::string &path, const bool quiet, const bool append)
      : file(path, append ? std::ios::app : std::ios::trunc)
      , quiet(quiet)
    {
      if (!file)
        throw std::runtime_error("cannot write the log file '" + path + "'");
      record_output_file(path);
    }

    void
    RunLog::operator()(const std::string &line)
    {
      if (!quiet)
        std::cout << line << std::endl;
      log_only(line);
    }

    void
    RunLog::log_only(const std::string &line)
    {
      file << line << std::endl;
    }

    PVDSeries::PVDSeries(const std::string &pvd_path)
      : path(pvd_path)
    {}

    void
    PVDSeries::add(const double time, const std::string &vtu_file_name)
    {
      entries.emplace_back(time, vtu_file_name);
      write();
    }

    void
    PVDSeries::save(CheckpointWriter &w) const
    {
      w.put(std::uint64_t(entries.size()));
      for (const auto &e : entries)
        {
          w.put(e.first);
          w.put(e.second);
        }
    }

    void
    PVDSeries::load(CheckpointReader &r)
    {
      entries.resize(r.get_size());
      for (auto &e : entries)
        {
          e.first  = r.get_double();
          e.second = r.get_string();
        }
      write();
    }

    PathCollections::PathCollections(const std::string &directory, const std::string &stem)
      : directory(directory)
      , stem(stem)
      , all(directory + "/" + stem + ".pvd")
    {}

    PVDSeries &
    PathCollections::branch(const unsigned int b)
    {
      auto it = branches.find(b);
      if (it == branches.end())
        it = branches
               .emplace(b, PVDSeries(directory + "/" + stem + "-branch-" + std::to_string(b) + ".pvd"))
               .first;
      return it->second;
    }

    void
    PathCollections::add(const unsigned int step,
                         const unsigned int b,
                         const double       t,
                         const std::string &vtu_file_name)
    {
      all.add(step, vtu_file_name);
      branch(b).add(t, vtu_file_name);
    }

    void
    PathCollections::save(CheckpointWriter &w) const
    {
      all.save(w);
      w.put(std::uint64_t(branches.size()));
      for (const auto &[b, series] : branches)
        {
          w.put(b);
          series.save(w);
        }
    }

    void
    PathCollections::load(CheckpointReader &r)
    {
      all.load(r);
      branches.clear();
      for (std::uint64_t i = 0, n = r.get_size(); i < n; ++i)
        branch(r.get_unsigned()).load(r);
    }

    void
    CSVTable::save(CheckpointWriter &w) const
    {
      w.put(std::uint64_t(columns.size()));
      w.put(std::uint64_t(rows.size()));
      for (const auto &row : rows)
        w.put_vector(row);
    }

    void
    CSVTable::load(CheckpointReader &r)
    {
      if (r.get_size() != columns.size())
        throw std::runtime_error("the checkpoint's table has other columns than this run's");
      rows.resize(r.get_size());
      for (auto &row : rows)
        row = r.get_vector();
    }

    void
    PVDSeries::write() const
    {
      write_file_atomically(path, [&](std::ostream &out) {
        out << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            << "  <Collection>\n";
        for (const auto &e : entries)
          out << "    <DataSet timestep=\"" << format_number(e.first)
              << "\" group=\"\" part=\"0\" file=\"" << e.second << "\"/>\n";
        out << "  </Collection>\n</VTKFile>\n";
      });
    }

    PhaseTimer::Scope::Scope(PhaseTimer &timer, const std::string &phase)
      : timer(timer)
      , phase(phase)
      , start(std::chrono::steady_clock::now())
    {}

    PhaseTimer::Scope::~Scope()
    {
      timer.add(phase,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }

    void
    PhaseTimer::add(const std::string &phase, const double s)
    {
      auto it = data.find(phase);
      if (it == data.end())
        {
          order.push_back(phase);
          data[phase] = {s, 1};
        }
      else
        {
          it->second.first += s;
          it->second.second += 1;
        }
    }

    double
    PhaseTimer::seconds(const std::string &phase) const
    {
      const auto it = data.find(phase);
      return it == data.end() ? 0. : it->second.first;
    }

    unsigned int
    PhaseTimer::calls(const std::string &phase) const
    {
      const auto it = data.find(phase);
      return it == data.end() ? 0 : it->second.second;
    }

    JSON
    PhaseTimer::to_json() const
    {
      JSON j = JSON::object();
      for (const auto &p : order)
        {
          j[p]["seconds"] = JSON(seconds(p));
          j[p]["calls"]   = JSON(calls(p));
        }
      return j;
    }
  } // namespace io
} // namespace cosmo
