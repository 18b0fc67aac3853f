// Boost's binary archives, declared for the headers whose classes save and
// load themselves (checkpoints); their sources include the archives.
#ifndef tribodyn_core_archive_fwd_h
#define tribodyn_core_archive_fwd_h

namespace boost
{
  namespace archive
  {
    class binary_oarchive;
    class binary_iarchive;
  } // namespace archive
} // namespace boost

#endif
