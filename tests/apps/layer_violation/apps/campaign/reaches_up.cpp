// A campaign file that reaches up into the command's own commands: the layer check must refuse it.
#include "../frictionlab/commands/command.hpp"
