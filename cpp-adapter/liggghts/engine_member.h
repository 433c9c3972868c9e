// Naming a member the engine keeps private or protected (LAMMPS's Modify:
// its style tables, the restart file's fix lists): the standard-conforming
// way, as an explicit instantiation may take the address of any member.
//   GRANBOND_ENGINE_MEMBER(Tag, Type, &Class::member);   // at namespace scope
//   object->*member(Tag())                               // the member
#ifndef GRANBOND_LIGGGHTS_ENGINE_MEMBER_H
#define GRANBOND_LIGGGHTS_ENGINE_MEMBER_H

namespace granbond {
namespace liggghts {

template<typename Tag, typename Tag::type Member>
struct ExposeMember {
    friend typename Tag::type member(Tag) { return Member; }
};

}
}

#define GRANBOND_ENGINE_MEMBER(Tag, Type, address)                                                           \
    struct Tag {                                                                                             \
        typedef Type type;                                                                                   \
        friend type member(Tag);                                                                             \
    };                                                                                                       \
    template struct ::granbond::liggghts::ExposeMember<Tag, address>

#endif
