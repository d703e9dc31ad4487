#include "facondeframer.h"
