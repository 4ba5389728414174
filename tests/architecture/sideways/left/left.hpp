#pragma once
#include "ancfnet/right/right.hpp"
