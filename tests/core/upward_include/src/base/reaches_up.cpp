// A base file that reaches up into the simulation layer: the layer check must refuse it.
#include "frictionlab/simulation/run.hpp"
