using System;

namespace AOT
{
    // Unity's IL2CPP (and Mono's full AOT) compile every method a native library may call back into
    // ahead of time, and find those methods by this attribute's name: AOT.MonoPInvokeCallbackAttribute.
    // Unity ships no such type outside its engine assemblies, so projects define it themselves, as here;
    // the runtime matches the name only. A callback so marked must be a static method whose delegate type
    // is given, and must not be generic.
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        public MonoPInvokeCallbackAttribute(Type delegateType) { DelegateType = delegateType; }

        public Type DelegateType { get; private set; }
    }
}
