#include "ancfnet/high/high.hpp"
#include "ancfnet/left/left.hpp"
#include "ancfnet/low/low.hpp"
#include "ancfnet/right/right.hpp"
