/*
 * pcl_rspd tools: the command-line conventions the tools share (usage errors, "--name value" and
 * "--name=value", strict integers), so each tool's parser only lists its options.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <charconv>
#include <string>
#include <system_error>

namespace rspd_tools
{
/** \brief A usage error: message for stderr, exit status 2. */
struct UsageError
{
  std::string message;
};

/** \brief The option at argv[i]: its name, and its value inline ("--name=value") or as the next
  * argument ("--name value"), which value() then consumes by advancing \a i. */
class OptionArgument
{
public:
  OptionArgument (int argc, char** argv, int& i) : argc_ (argc), argv_ (argv), i_ (i), name_ (argv[i])
  {
    const std::size_t eq = name_.find ('=');
    if (name_.compare (0, 2, "--") == 0 && eq != std::string::npos)
    {
      inline_value_ = name_.substr (eq + 1);
      name_.resize (eq);
      has_inline_ = true;
    }
  }

  /** \brief The option without any inline value. */
  const std::string&
  name () const { return name_; }

  /** \brief The option's value. \throws UsageError when there is none */
  std::string
  value ()
  {
    if (has_inline_)
      return inline_value_;
    if (i_ + 1 >= argc_)
      throw UsageError{"option " + name_ + " needs a value"};
    return argv_[++i_];
  }

  /** \brief For a flag. \throws UsageError when it was given an inline value */
  void
  noValue () const
  {
    if (has_inline_)
      throw UsageError{"option " + name_ + " takes no value"};
  }

  /** \brief A value that must be one of two words. \return whether it is \a yes \throws UsageError */
  bool
  choice (const char* yes, const char* no)
  {
    const std::string v = value ();
    if (v != yes && v != no)
      throw UsageError{name_ + " needs '" + yes + "' or '" + no + "' (got '" + v + "')"};
    return v == yes;
  }

private:
  int argc_;
  char** argv_;
  int& i_;
  std::string name_;
  std::string inline_value_;
  bool has_inline_ = false;
};

/** \brief Parse the whole string as a decimal integer in [lo, hi] (no sign games, no overflow). */
template <typename T>
bool
parseInteger (const std::string& s, T lo, T hi, T& value)
{
  const char* end = s.data () + s.size ();
  T parsed{};
  const auto r = std::from_chars (s.data (), end, parsed);
  if (s.empty () || r.ec != std::errc () || r.ptr != end || parsed < lo || parsed > hi)
    return false;
  value = parsed;
  return true;
}
} // namespace rspd_tools
