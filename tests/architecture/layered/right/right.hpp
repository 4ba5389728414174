#pragma once
#include "ancfnet/low/low.hpp"
