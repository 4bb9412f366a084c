#include <cosmo/io/stderr_capture.h>

#include <unistd.h>

#include <cctype>

namespace cosmo
{
  namespace io
  {
    StderrCapture::StderrCapture()
    {
      std::fflush(stderr);
      file = std::tmpfile();
      if (file == nullptr)
        return; // nothing to capture into: stderr stays as it is
      saved = ::dup(2);
      if (saved < 0 || ::dup2(::fileno(file), 2) < 0)
        {
          if (saved >= 0)
            ::close(saved);
          saved = -1;
          std::fclose(file);
          file = nullptr;
        }
    }

    StderrCapture::~StderrCapture()
    {
      release();
    }

    std::string
    StderrCapture::release()
    {
      if (file == nullptr)
        return "";
      std::fflush(stderr);
      ::dup2(saved, 2);
      ::close(saved);
      saved = -1;
      std::string text;
      std::rewind(file);
      bool space = false;
      for (int c; (c = std::fgetc(file)) != EOF;)
        {
          if (c == '\n' || std::isspace(c))
            {
              space = !text.empty();
              continue;
            }
          if (c == '[' && !text.empty())
            text += "; "; // a new block ("[KINSOL ERROR] ...")
          else if (space)
            text += ' ';
          space = false;
          text += static_cast<char>(c);
        }
      std::fclose(file);
      file = nullptr;
      return text;
    }
  } // namespace io
} // namespace cosmo
