/* datadir.c: the data directory an installed gallop was built for (`make install` bakes
 * $(PREFIX)/share/gallop in as GAL_DATADIR; empty in a build tree, where data/ is used). */
#include "gallop/base/datadir.h"

#ifndef GAL_DATADIR
#define GAL_DATADIR ""
#endif

const char *gal_datadir_installed(void) { return GAL_DATADIR; }
