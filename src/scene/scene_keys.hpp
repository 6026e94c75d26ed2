// How a scene key is declared: once, with its name, the member of the scene's structs it fills,
// how it is read (its type and limits) and how it is written. The loader reads a section by
// walking its declarations (readKeys), sceneToJson writes it by the same walk (writeKeys), and
// the schema that documents and `--set` paths are checked against is made of their names
// (schemaOf). A key's default is its member's initializer in include/sph/scene.hpp.
//
//   const SceneKeys<TimeDesc>& timeKeys() {
//     static const SceneKeys<TimeDesc> keys{{
//         number("duration", at(&TimeDesc::duration), kDuration),
//         optionalNumber("fixed_dt", at(&TimeDesc::fixedDt), kTimeStep),
//     }};
//     return keys;
//   }
//
// The scene's own declarations are in scene_keys.cpp.
#pragma once

#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_reader.hpp"
#include "scene/scene_schema.hpp"

namespace sph::scene {

// Where a key's value lives in a Desc: a member.
template <class Desc, class T>
struct Field {
  std::function<T&(Desc&)> get;
  std::function<const T&(const Desc&)> read;
};

template <class Desc, class T>
Field<Desc, T> at(T Desc::*member) {
  return {[member](Desc& d) -> T& { return d.*member; },
          [member](const Desc& d) -> const T& { return d.*member; }};
}

template <class Desc>
struct SceneKey {
  std::string name;
  std::function<void(const ObjectReader&, Desc&)> read;
  std::function<void(const Desc&, nlohmann::json&)> write;  // sets out[name]
  KeySchema schema;                                         // the key and what lies below it
  // Only where this holds (a wall's radius: spheres and cylinders). Read after the keys
  // before it, so it may look at the type they read; elsewhere the key is refused.
  std::function<bool(const Desc&)> appliesTo;

  SceneKey only(std::function<bool(const Desc&)> where) && {
    appliesTo = std::move(where);
    return std::move(*this);
  }
};

template <class Desc>
struct SceneKeys {
  SceneKeys(std::vector<SceneKey<Desc>> declared, std::function<std::string(const Desc&)> kind = {})
      : keys(std::move(declared)), kindOf(std::move(kind)) {}

  std::vector<SceneKey<Desc>> keys;
  // For keys that apply to some kinds only: the kind a refusal names ("sphere wall").
  std::function<std::string(const Desc&)> kindOf;
};

template <class Desc>
bool applies(const SceneKey<Desc>& key, const Desc& desc) {
  return !key.appliesTo || key.appliesTo(desc);
}

// A name may be declared twice, read differently by different kinds (a sphere wall's centre is
// required, a mesh's is not); the schema holds it once.
template <class Desc>
KeySchema schemaOf(const std::string& name, const SceneKeys<Desc>& table) {
  KeySchema schema{name, KeySchema::Shape::Object, {}};
  for (const SceneKey<Desc>& key : table.keys)
    if (schema.find(key.name) == nullptr) schema.children.push_back(key.schema);
  return schema;
}

template <class Desc>
void readKeys(const ObjectReader& in, const SceneKeys<Desc>& table, Desc& out) {
  for (const SceneKey<Desc>& key : table.keys) {
    if (applies(key, out)) {
      key.read(in, out);
      continue;
    }
    if (!in.has(key.name)) continue;
    const auto sameName = [&](const SceneKey<Desc>& k) {
      return k.name == key.name && applies(k, out);
    };
    if (std::any_of(table.keys.begin(), table.keys.end(), sameName)) continue;
    // A key of another kind is a mistake, not something to ignore.
    std::string list;
    for (const SceneKey<Desc>& k : table.keys)
      if (applies(k, out)) list += (list.empty() ? "" : ", ") + k.name;
    in.context().fail(in.keyPath(key.name),
                      "not a key of a " + table.kindOf(out) + "; its keys are " + list);
  }
}

template <class Desc>
nlohmann::json writeKeys(const Desc& desc, const SceneKeys<Desc>& table) {
  nlohmann::json out = nlohmann::json::object();
  for (const SceneKey<Desc>& key : table.keys)
    if (applies(key, desc)) key.write(desc, out);
  return out;
}

inline KeySchema valueSchema(const std::string& name) {
  return {name, KeySchema::Shape::Value, {}};
}

inline KeySchema vec3Schema(const std::string& name) {
  return {name, KeySchema::Shape::Array, {valueSchema("[]")}};
}

inline KeySchema requiredSchema(KeySchema schema) {
  schema.required = true;
  return schema;
}

// --- Values -------------------------------------------------------------------------------

template <class Desc>
SceneKey<Desc> number(const std::string& name, Field<Desc, double> f, NumberRule rule) {
  return {name,
          [=](const ObjectReader& in, Desc& d) { f.get(d) = in.number(name, f.get(d), rule); },
          [=](const Desc& d, nlohmann::json& out) { out[name] = f.read(d); },
          valueSchema(name),
          {}};
}

// Present and within `rule`; `what` says what is missing ("a length in m").
template <class Desc>
SceneKey<Desc> requiredNumber(const std::string& name, Field<Desc, double> f, NumberRule rule,
                              const std::string& what) {
  return {name,
          [=](const ObjectReader& in, Desc& d) {
            if (!in.has(name))
              in.context().fail(in.keyPath(name), "required key is missing (" + what + ")");
            f.get(d) = in.number(name, f.get(d), rule);
          },
          [=](const Desc& d, nlohmann::json& out) { out[name] = f.read(d); },
          requiredSchema(valueSchema(name)),
          {}};
}

// Absent or null: unset (the value is then derived).
template <class Desc>
SceneKey<Desc> optionalNumber(const std::string& name, Field<Desc, std::optional<double>> f,
                              NumberRule rule) {
  return {name,
          [=](const ObjectReader& in, Desc& d) { f.get(d) = in.optionalNumber(name, rule); },
          [=](const Desc& d, nlohmann::json& out) {
            const std::optional<double>& value = f.read(d);
            out[name] = value ? nlohmann::json(*value) : nlohmann::json(nullptr);
          },
          valueSchema(name),
          {}};
}

template <class Desc>
SceneKey<Desc> integer(const std::string& name, Field<Desc, int> f, int lo, int hi) {
  return {name,
          [=](const ObjectReader& in, Desc& d) { f.get(d) = in.integer(name, f.get(d), lo, hi); },
          [=](const Desc& d, nlohmann::json& out) { out[name] = f.read(d); },
          valueSchema(name),
          {}};
}

template <class Desc>
SceneKey<Desc> boolean(const std::string& name, Field<Desc, bool> f) {
  return {name,
          [=](const ObjectReader& in, Desc& d) { f.get(d) = in.boolean(name, f.get(d)); },
          [=](const Desc& d, nlohmann::json& out) { out[name] = f.read(d); },
          valueSchema(name),
          {}};
}

template <class Desc>
SceneKey<Desc> text(const std::string& name, Field<Desc, std::string> f) {
  return {name,
          [=](const ObjectReader& in, Desc& d) { f.get(d) = in.string(name, f.get(d)); },
          [=](const Desc& d, nlohmann::json& out) { out[name] = f.read(d); },
          valueSchema(name),
          {}};
}

// Each coordinate at most `largest` in magnitude.
template <class Desc>
SceneKey<Desc> vec3(const std::string& name, Field<Desc, Vec3d> f,
                    double largest = kLargestCoordinate) {
  return {name,
          [=](const ObjectReader& in, Desc& d) { f.get(d) = in.vec3(name, f.get(d), largest); },
          [=](const Desc& d, nlohmann::json& out) { out[name] = f.read(d); },
          vec3Schema(name),
          {}};
}

// Each coordinate within [lo, hi].
template <class Desc>
SceneKey<Desc> vec3Within(const std::string& name, Field<Desc, Vec3d> f, double lo, double hi) {
  return {
      name,
      [=](const ObjectReader& in, Desc& d) { f.get(d) = in.vec3Within(name, f.get(d), lo, hi); },
      [=](const Desc& d, nlohmann::json& out) { out[name] = f.read(d); },
      vec3Schema(name),
      {}};
}

template <class Desc>
SceneKey<Desc> requiredVec3(const std::string& name, Field<Desc, Vec3d> f,
                            double largest = kLargestCoordinate) {
  return {name,
          [=](const ObjectReader& in, Desc& d) { f.get(d) = in.requiredVec3(name, largest); },
          [=](const Desc& d, nlohmann::json& out) { out[name] = f.read(d); },
          requiredSchema(vec3Schema(name)),
          {}};
}

template <class Desc, class Enum, std::size_t N>
SceneKey<Desc> choice(const std::string& name, Field<Desc, Enum> f,
                      const NamedValue<Enum> (&names)[N]) {
  const NamedValue<Enum>* table = names;
  return {
      name,
      [=, &names](const ObjectReader& in, Desc& d) { f.get(d) = in.choice(name, f.get(d), names); },
      [=](const Desc& d, nlohmann::json& out) {
        for (std::size_t i = 0; i < N; ++i)
          if (table[i].value == f.read(d)) out[name] = table[i].name;
      },
      valueSchema(name),
      {}};
}

// A key read and written by hand, for what a declaration cannot say (a default that depends on
// another key, a value stored in another form).
template <class Desc>
SceneKey<Desc> custom(const std::string& name, std::function<void(const ObjectReader&, Desc&)> read,
                      std::function<nlohmann::json(const Desc&)> write, KeySchema schema = {}) {
  if (schema.name.empty()) schema = valueSchema(name);
  return {name,
          std::move(read),
          [name, write = std::move(write)](const Desc& d, nlohmann::json& out) {
            out[name] = write(d);
          },
          std::move(schema),
          {}};
}

// --- Objects and arrays ----------------------------------------------------------------------

// An object of its own in the file, a struct of its own in the scene (fluid.dfsph).
template <class Desc, class Sub>
SceneKey<Desc> section(const std::string& name, Field<Desc, Sub> f, const SceneKeys<Sub>& table,
                       bool required = false) {
  return {
      name,
      [=, &table](const ObjectReader& in, Desc& d) {
        readKeys(required ? in.requiredObject(name) : in.object(name), table, f.get(d));
      },
      [=, &table](const Desc& d, nlohmann::json& out) { out[name] = writeKeys(f.read(d), table); },
      schemaOf(name, table),
      {}};
}

// An object of its own in the file whose keys fill the enclosing struct (fluid.viscosity).
template <class Desc>
SceneKey<Desc> group(const std::string& name, const SceneKeys<Desc>& table) {
  return {name,
          [=, &table](const ObjectReader& in, Desc& d) { readKeys(in.object(name), table, d); },
          [=, &table](const Desc& d, nlohmann::json& out) { out[name] = writeKeys(d, table); },
          schemaOf(name, table),
          {}};
}

// An array of objects. `prepare` sets an element's defaults before its keys are read (a name
// from its index).
template <class Desc, class Element>
SceneKey<Desc> list(const std::string& name, Field<Desc, std::vector<Element>> f,
                    const SceneKeys<Element>& table, bool required = false, bool nonEmpty = false,
                    std::function<void(Element&, std::size_t)> prepare = {}) {
  KeySchema element = schemaOf("[]", table);
  return {name,
          [=, &table](const ObjectReader& in, Desc& d) {
            std::vector<Element>& items = f.get(d);
            items.clear();
            for (const ObjectReader& itemIn : in.objectArray(name, required, nonEmpty)) {
              Element item;
              if (prepare) prepare(item, items.size());
              readKeys(itemIn, table, item);
              items.push_back(std::move(item));
            }
          },
          [=, &table](const Desc& d, nlohmann::json& out) {
            nlohmann::json items = nlohmann::json::array();
            for (const Element& item : f.read(d)) items.push_back(writeKeys(item, table));
            out[name] = std::move(items);
          },
          KeySchema{name, KeySchema::Shape::Array, {std::move(element)}},
          {}};
}

// The "min" and "max" of an axis-aligned box, both required.
template <class Desc>
SceneKey<Desc> boxMin(Field<Desc, AxisBox> box) {
  return requiredVec3<Desc>("min",
                            {[box](Desc& d) -> Vec3d& { return box.get(d).min; },
                             [box](const Desc& d) -> const Vec3d& { return box.read(d).min; }});
}

template <class Desc>
SceneKey<Desc> boxMax(Field<Desc, AxisBox> box) {
  return requiredVec3<Desc>("max",
                            {[box](Desc& d) -> Vec3d& { return box.get(d).max; },
                             [box](const Desc& d) -> const Vec3d& { return box.read(d).max; }});
}

// Every key of a scene file (scene_keys.cpp).
const SceneKeys<Scene>& sceneKeys();

// Gives each unnamed wall, object, probe, emitter and outlet the name the loader gives it
// ("wall2": the third wall): a scene built in code may leave them empty.
void nameUnnamedElements(Scene& scene);

}  // namespace sph::scene
