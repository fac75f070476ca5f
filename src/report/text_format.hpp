#pragma once
// Text for the study's report: HTML escaping, base64 (images as data URIs), numbers rounded as a
// reader rounds them, p-values and effect sizes in words.
#include <string>
#include <string_view>

namespace imasim::report {

// &, <, >, " and ' as entities.
std::string html_escape(std::string_view text);

// RFC 4648 base64 with padding.
std::string base64(std::string_view bytes);

// `value` with `decimals` digits after the point, rounded half away from zero on its shortest
// decimal form (0.2475 -> "0.248", as printed by hand; printf would round the binary 0.24749...
// down); "-" for a value that is not finite.
std::string fixed(double value, int decimals);

// "mean ± sd" with `decimals` digits each.
std::string mean_sd(double mean, double sd, int decimals);

// "p < 0.001" below 0.001, else "p = 0.034" (three digits).
std::string p_text(double p);

// Cohen's |d| in words (Cohen 1988, Sawilowsky 2009): negligible, small, medium, large,
// very large, huge.
std::string effect_size_words(double d);

// Wall-clock seconds as "1:05" or "1:02:05".
std::string clock_text(double seconds);

}  // namespace imasim::report
