#pragma once
// Boost.Odeint (header-only) as a system header: it does not build warning-free under the
// project's -Wconversion -Wshadow.
#pragma GCC system_header
#include <boost/numeric/odeint.hpp>
