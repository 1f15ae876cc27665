#include "bezel/font.hpp"
