// Unit tests are exempt: they may use any part.
#include "ancfnet/high/high.hpp"
