using System.Runtime.InteropServices;

namespace NavLink
{
    /// <summary>Three floats, laid out as the header's float[3] fields (x y z, metres, Y up).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Vec3
    {
        public float X, Y, Z;

        public Vec3(float x, float y, float z) { X = x; Y = y; Z = z; }

        public static Vec3 operator -(Vec3 a, Vec3 b) { return new Vec3(a.X - b.X, a.Y - b.Y, a.Z - b.Z); }

        public float HorizontalDistance(Vec3 other)
        {
            float dx = X - other.X, dz = Z - other.Z;
            return (float)System.Math.Sqrt(dx * dx + dz * dz);
        }

        public override string ToString() { return string.Format("({0:0.###} {1:0.###} {2:0.###})", X, Y, Z); }
    }
}
