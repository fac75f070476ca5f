#include "report/text_format.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace imasim::report {

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64(std::string_view bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    std::uint32_t group = std::uint32_t(static_cast<unsigned char>(bytes[i])) << 16;
    if (left > 1) group |= std::uint32_t(static_cast<unsigned char>(bytes[i + 1])) << 8;
    if (left > 2) group |= std::uint32_t(static_cast<unsigned char>(bytes[i + 2]));
    out += kDigits[(group >> 18) & 63];
    out += kDigits[(group >> 12) & 63];
    out += left > 1 ? kDigits[(group >> 6) & 63] : '=';
    out += left > 2 ? kDigits[group & 63] : '=';
  }
  return out;
}

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "-";
  // Twelve significant digits drop the binary representation's tail (0.24749999999999999778
  // is 0.2475) before the decimal rounding.
  char shortest[40];
  std::snprintf(shortest, sizeof shortest, "%.12g", value * std::pow(10.0, decimals));
  const double scaled = std::round(std::strtod(shortest, nullptr));
  char out[64];
  std::snprintf(out, sizeof out, "%.*f", decimals, scaled / std::pow(10.0, decimals));
  const std::string text = out;
  // No "-0.000".
  if (scaled == 0 && text.front() == '-') return text.substr(1);
  return text;
}

std::string mean_sd(double mean, double sd, int decimals) {
  return fixed(mean, decimals) + " ± " + fixed(sd, decimals);
}

std::string p_text(double p) {
  if (p < 0.001) return "p < 0.001";
  return "p = " + fixed(p, 3);
}

std::string effect_size_words(double d) {
  const double a = std::abs(d);
  if (a < 0.2) return "negligible";
  if (a < 0.5) return "small";
  if (a < 0.8) return "medium";
  if (a < 1.2) return "large";
  if (a < 2.0) return "very large";
  return "huge";
}

std::string clock_text(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  char out[32];
  if (total >= 3600)
    std::snprintf(out, sizeof out, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  else
    std::snprintf(out, sizeof out, "%ld:%02ld", total / 60, total % 60);
  return out;
}

}  // namespace imasim::report
