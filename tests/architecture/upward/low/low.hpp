#pragma once
#include "ancfnet/high/high.hpp"
