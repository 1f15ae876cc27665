#include "bezel/bezier.hpp"
