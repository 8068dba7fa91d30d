/* placeholder */
#include "ana.h"
